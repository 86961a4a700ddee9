// Spatial directional radiance caching on the device (DESIGN.md §6.5; Gassenbauer, Křivánek and
// Bouatouch, "Spatial Directional Radiance Caching", EGSR 2009, "SDRC" below; `radcache render
// --method sdrc`): the glossy lobes' cache beside irradiance caching's diffuse records. Per
// frame: the camera samples on a specular lobe; records placed coarse to fine where those samples
// are not covered (GlossyPlacement), each N directions importance-sampled from its site's lobe,
// traced, kept as an L-tree (a kd-tree of quantised paraboloid-map positions and RGBE radiance,
// built on the host); then the interpolation in rounds (strides 16, 8, 4, 2, 1 of the image, as
// the placement): every camera sample of the round draws M lobe directions and range-queries the
// covering records' L-trees; the directions no L-tree answers are traced from a contributing
// record and inserted into its L-tree at the end of the round, so the next round finds them. The
// result is the glossy buffer irradiance caching's render pass reads. Deterministic whatever the
// batch, chunk or work-group size: the trees change only between rounds, in sample order.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "methods/caching/cache_pipeline.h"
#include "methods/caching/glossy_cache.h"
#include "methods/caching/glossy_placement.h"
#include "methods/caching/record_store.h"
#include "methods/frame_scene.h"
#include "methods/sdrc/ltree.h"
#include "methods/shared_settings.h"
#include "shared/sdrc.h"

namespace rc {

// Of the shared settings, the seed and depth limits apply (those of the irradiance records).
struct SdrcOptions : SharedSettings {
    int samples = 0;             // N, directions of a new record; 0: auto (sdrc_record_samples)
    int interp = 4;              // M, directions per camera sample (SDRC §4.4)
    float max_radius = 0.15f;    // r_max in D (SDRC §4.4)
    double memory_mib = 4096.0;  // cap on the L-trees' nodes
    float accuracy = 0.35f;      // a (shared with irradiance caching's --accuracy)
    Spacing min_spacing{8.0f, false};
    Spacing max_spacing{64.0f, false};
    bool count_emission = false;  // count emitters the rays see (tests)
    // Records per record launch and camera samples per interpolation launch (0: the defaults);
    // the image does not depend on them (tests).
    size_t record_batch = 0;
    size_t round_batch = 0;
    ServedMaterials materials;  // the materials served (empty: every one; GlossyCache)
};

// Directions of a new record for these options at `spp` camera samples per pixel: N if given,
// else 3 M spp within [64, 8192]. SDRC §4.3 takes N ≈ 12 M, M the directions a shading point
// draws: with the query radius of §4.4 a direction then finds about N / 2M = 6 samples in the
// record's L-tree. Here a pixel's M spp directions set the radius, and a camera sample is covered
// by about 4 records (measured on the kettle: 4.0 range queries per direction) whose found
// samples all count, so N = 12 M spp / 4 keeps about 6 found samples per direction.
int sdrc_record_samples(const SdrcOptions& options, int spp);

// Samples an L-tree's buffer holds before the tree is rebuilt over them (SDRC §4.4).
inline constexpr size_t kLTreeBufferCapacity = 32;

struct SdrcStats {
    GlossyPlacementStats placement;  // record_seconds: record rays and L-tree builds
    int samples = 0;                 // N
    size_t records = 0;
    uint64_t ltree_nodes = 0;  // at the end, trees and buffers
    uint64_t record_rays = 0;
    uint64_t miss_rays = 0;
    uint64_t directions = 0;     // interpolation directions drawn (M per served camera sample)
    uint64_t answered = 0;       // of those, answered from the L-trees
    uint64_t range_queries = 0;  // L-trees queried (each direction queries every covering record)
    uint64_t misses = 0;         // traced: inserted into an L-tree, or from the camera sample
    uint64_t unstored = 0;  // of the misses, no record could take them (traced from the sample)
    size_t rebuilds = 0;
    double query_seconds = 0.0;
    double tree_build_seconds = 0.0;  // the host's L-tree builds (in record_seconds) and rebuilds
    double interpolation_seconds = 0.0;  // range queries, miss rays and insertions
};

// A batch of SDRC records as the record kernel computed them, still on the device, before their
// L-trees are built.
struct SdrcBatch {
    const shared::SdrcParams& params;
    const Buffer<shared::RcQuery>& sites;    // count sites
    const Buffer<unsigned>& streams;         // their random streams
    const Buffer<shared::float4>& samples;   // count x N: (L.rgb, hit distance)
    const Buffer<shared::LTreeNode>& nodes;  // count x N: the samples' nodes, in sample order
    const Buffer<shared::float4>& cells;     // count x M N uniform cells (the observer's M x N)
    const shared::RcQuery* site_values;      // the same sites and streams on the host
    const unsigned* stream_values;
    const RadianceSource& diffuse;  // what the samples' rays read beyond their hits
    size_t count;
};

// Shown every batch of records before their L-trees are built (temporal caching reprojects
// them: host/methods/sdrc/tc_sdrc_reprojection.h).
class SdrcBatchObserver {
   public:
    virtual ~SdrcBatchObserver() = default;
    // The M x N uniform cells of each record's hemisphere the record kernel also traces for the
    // observer (SdrcBatch::cells; sdrc_record_samples).
    virtual int cell_rows() const = 0;
    virtual int cell_columns() const = 0;
    virtual void observe(const SdrcBatch& batch) = 0;
};

// The camera samples as SDRC sees them, and their glossy-buffer entries.
struct SdrcQueries {
    Buffer<shared::RcQuery> queries;
    Buffer<shared::RcGlossySample> glossy;
};

class SdrcCache final : public GlossyCache, private FrameBound {
   public:
    SdrcCache(const FrameScene& frame, const SdrcOptions& options);

    // queries(), place() and interpolate() in turn: the glossy buffer.
    Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                  const shared::CameraParams& camera,
                                                  const RadianceSource& diffuse) override;

    // The camera samples of `camera`'s image (entry pixel * spp + s), every glossy-buffer entry
    // cleared.
    SdrcQueries queries(const shared::IcParams& params, const shared::CameraParams& camera);
    // Records placed, coarse to fine, where the served queries are not covered (GlossyPlacement).
    void place(const Buffer<shared::RcQuery>& queries, const shared::IcParams& params,
               const RadianceSource& diffuse);
    // After place(): the interpolation, round by round, into queries.glossy.
    void interpolate(SdrcQueries& queries, const shared::IcParams& params,
                     const RadianceSource& diffuse);
    // Records at `sites` with the given random streams (one each), inserted in order.
    void add_records(const std::vector<shared::RcQuery>& sites,
                     const std::vector<unsigned>& streams, const shared::IcParams& params,
                     const RadianceSource& diffuse);
    // Replaces the records: `store`, the sites they were made at and their L-trees (one each);
    // new records take streams from `next_stream` on.
    void set_records(RecordStore store, std::vector<shared::RcQuery> sites,
                     std::vector<LTree> trees, unsigned next_stream);
    // Per record of `store`: 1 where a served query weighs it positively.
    std::vector<uint8_t> records_used(const Buffer<shared::RcQuery>& queries,
                                      const RecordStore& store) {
        return placement_.records_used(queries, store);
    }
    void set_observer(SdrcBatchObserver* observer) { observer_ = observer; }
    unsigned next_stream() const { return next_stream_; }
    uint64_t rays() const override { return stats_.record_rays + stats_.miss_rays; }
    double record_seconds() const override {
        return stats_.placement.placement_seconds + stats_.placement.record_seconds;
    }
    std::vector<FilmLayer> layers() const override {
        return {{"sdrc-hits", RC_CACHED_FILM_HITS, 1}};
    }
    // The statistics file's "sdrc" object (sdrc_stats.cpp).
    nlohmann::json statistics() const override;

    const RecordStore& store() const { return store_; }
    const std::vector<LTree>& trees() const { return trees_; }
    const SdrcStats& stats() const { return stats_; }

   private:
    shared::SdrcParams kernel_params(const shared::IcParams& params) const;
    Kernel& trace_kernel(const RadianceSource& source, const char* name);
    // Records at `sites` with random streams `streams`: their L-trees built, inserted.
    void add_batches(const std::vector<shared::RcQuery>& sites,
                     const std::vector<unsigned>& streams, const shared::SdrcParams& params,
                     const RadianceSource& diffuse);
    // One interpolation round over `samples` (ascending camera-sample indices).
    void interpolate_round(const std::vector<uint32_t>& samples, const shared::SdrcParams& params,
                           const Buffer<shared::RcQuery>& queries,
                           Buffer<shared::RcGlossySample>& glossy, const RadianceSource& diffuse);
    // Error (exit status 1) when the L-trees hold more than the memory cap.
    void check_memory();

    SdrcOptions options_;
    SdrcStats stats_;
    RecordStore store_;
    std::vector<LTree> trees_;            // one per record
    std::vector<shared::RcQuery> sites_;  // where each record was made
    unsigned next_stream_ = 0;            // the random stream of the next new record
    SdrcBatchObserver* observer_ = nullptr;
    Kernel queries_kernel_;
    Kernel radius_kernel_;
    Kernel interpolate_kernel_;
    Kernel add_misses_kernel_;
    std::map<std::string, Kernel> trace_kernels_;  // by name and build options
    GlossyPlacement placement_;
};

}  // namespace rc
