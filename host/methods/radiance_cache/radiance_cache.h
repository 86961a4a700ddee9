// Radiance caching on the device (DESIGN.md §6.4; Křivánek et al., "Radiance Caching for
// Efficient Global Illumination Computation", TVCG 2005; `radcache render --method rc`): the
// glossy lobes' cache beside irradiance caching's diffuse records. Per frame: the scene's BRDF
// tables with their adaptive orders; the camera samples whose specular lobe the tables represent;
// records placed coarse to fine where those samples are not covered, each the SH projection of
// its hemisphere's incoming radiance with translational gradients, inserted with the shared
// record store's radius rules; then every such sample's interpolated reflection, the glossy
// buffer irradiance caching's render pass reads. Owns its buffers; reports its statistics.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "methods/caching/cache_pipeline.h"
#include "methods/caching/glossy_cache.h"
#include "methods/caching/glossy_placement.h"
#include "methods/caching/record_store.h"
#include "methods/frame_scene.h"
#include "methods/radiance_cache/brdf_tables.h"
#include "methods/shared_settings.h"

namespace rc {

// Of the shared settings, the seed and depth limits apply (those of the irradiance records).
struct RadianceCacheOptions : SharedSettings {
    int order = 0;           // n_max of the BRDF tables and the records; 0: auto (RC_SH_MAX_ORDER)
    double max_error = 0.1;  // the BRDF tables' largest representation error (TVCG §4.1)
    int rays = 4096;  // hemisphere rays per record (M x N strata, N ~ 4 M; TVCG §6: 4000-6000)
    float accuracy = 0.35f;            // a (shared with irradiance caching's --accuracy)
    Spacing min_spacing{8.0f, false};  // bounds on a record's radius R
    Spacing max_spacing{64.0f, false};
    bool count_emission = false;      // count emitters the hemisphere rays see (tests)
    std::filesystem::path cache_in;   // radiance records to start from (--rc-cache-in)
    std::filesystem::path cache_out;  // where to save the radiance records (--rc-cache-out)
    ServedMaterials materials;        // the materials served (empty: every one; GlossyCache)
};

struct RadianceCacheStats {
    std::vector<BrdfTableSummary> materials;  // the adaptive order's split, per material
    int order = 0;                            // of the records (0: no glossy material)
    int strata_m = 0;
    int strata_n = 0;
    GlossyPlacementStats placement;  // record_seconds: hemisphere rays and projection
    size_t records = 0;              // at the end, loaded ones included
    size_t loaded_records = 0;       // from --rc-cache-in
    uint64_t record_rays = 0;
    uint64_t reflections = 0;  // record reflections evaluated (one rotation each)
    double table_seconds = 0.0;
    bool tables_built = false;  // by this cache (else built before on the device and kept)
    double query_seconds = 0.0;
    double splat_seconds = 0.0;  // the glossy buffer
};

// A batch of radiance records as the record kernel computed them, still on the device.
struct RadianceBatch {
    const shared::RcParams& params;
    const Buffer<shared::RcQuery>& sites;  // count sites
    const Buffer<unsigned>& streams;       // their random streams
    const Buffer<shared::float4>& cells;   // count x M N uniform cells: (L.rgb, hit distance)
    const shared::RcQuery* site_values;    // the same sites and streams on the host
    const unsigned* stream_values;
    size_t count;
};

// Shown every batch of records before their projection and insertion (temporal caching
// reprojects their hemisphere samples: host/methods/radiance_cache/tc_radiance_reprojection.h).
class RadianceBatchObserver {
   public:
    virtual ~RadianceBatchObserver() = default;
    virtual void observe(const RadianceBatch& batch) = 0;
};

// Error (exit status 2) naming the option radiance caching cannot honour.
void check_radiance_cache_options(const RadianceCacheOptions& options);

// M x N strata with N ~ 4 M (course, "Incoming Radiance Computation") and M N close to `rays`.
void radiance_strata(int rays, int* m, int* n);

class RadianceCache final : public GlossyCache, private FrameBound {
   public:
    // Builds the frame's BRDF tables (the adaptive order, TVCG §4.1), or takes `tables` when
    // given (built by an earlier cache of the same scene's materials, device and options); reads
    // options.cache_in.
    RadianceCache(const FrameScene& frame, const RadianceCacheOptions& options,
                  std::shared_ptr<const BrdfTables> tables = nullptr);

    // queries(), place() and splat() in turn, the records saved to options.cache_out between.
    Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                  const shared::CameraParams& camera,
                                                  const RadianceSource& diffuse) override;

    // The camera samples of `camera`'s image as radiance caching sees them (entry pixel * spp + s).
    Buffer<shared::RcQuery> queries(const shared::IcParams& params,
                                    const shared::CameraParams& camera);
    // Records placed, coarse to fine, where the served queries are not covered (GlossyPlacement).
    void place(const Buffer<shared::RcQuery>& queries, const shared::IcParams& params,
               const RadianceSource& diffuse);
    // The glossy buffer: every served query's interpolated reflection from the store's records.
    Buffer<shared::RcGlossySample> splat(const Buffer<shared::RcQuery>& queries);

    // Records at `sites` with the given random streams (one each), inserted in order.
    void add_records(const std::vector<shared::RcQuery>& sites,
                     const std::vector<unsigned>& streams, const RadianceSource& diffuse);
    // Replaces the store; new records take streams from `next_stream` on.
    void set_store(RecordStore store, unsigned next_stream);
    // Per record of `store` (order and payloads as this cache's): 1 where a served query
    // weighs it positively (the report's occlusion query for the records still in use).
    std::vector<uint8_t> records_used(const Buffer<shared::RcQuery>& queries,
                                      const RecordStore& store);
    void set_observer(RadianceBatchObserver* observer) { observer_ = observer; }
    unsigned next_stream() const { return next_stream_; }
    int order() const { return std::max(order_, 1); }
    // (Saves the records to options.cache_out at the end.)
    uint64_t rays() const override { return stats_.record_rays; }
    double record_seconds() const override {
        return stats_.table_seconds + stats_.placement.placement_seconds +
               stats_.placement.record_seconds;
    }
    std::vector<FilmLayer> layers() const override {
        return {{"rc-order", RC_CACHED_FILM_ORDER, 1}};
    }
    // The statistics file's "radiance_cache" object (radiance_cache_stats.cpp).
    nlohmann::json statistics() const override;

    const RecordStore& store() const { return store_; }
    const std::shared_ptr<const BrdfTables>& tables() const { return tables_; }
    const RadianceCacheStats& stats() const { return stats_; }

   private:
    shared::RcParams record_params() const;
    Kernel& cells_kernel(const RadianceSource& source);

    RadianceCacheOptions options_;
    RadianceCacheStats stats_;  // before tables_, which record their build time there
    std::shared_ptr<const BrdfTables> tables_;
    int order_ = 0;
    int strata_m_ = 1;
    int strata_n_ = 1;
    RecordStore store_;
    unsigned next_stream_ = 0;  // the random stream of the next new record
    RadianceBatchObserver* observer_ = nullptr;
    Kernel queries_kernel_;
    Kernel project_kernel_;
    Kernel splat_kernel_;
    GlossyPlacement placement_;
    std::map<std::string, Kernel> cells_kernels_;  // source_kernel's
};

}  // namespace rc
