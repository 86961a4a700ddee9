// Radiance caching on the device (DESIGN.md §6.4; Křivánek et al., "Radiance Caching for
// Efficient Global Illumination Computation", TVCG 2005; `radcache render --method rc`): the
// glossy lobes' cache beside irradiance caching's diffuse records. Per frame: the scene's BRDF
// tables with their adaptive orders; the camera samples whose specular lobe the tables represent;
// records placed coarse to fine where those samples are not covered, each the SH projection of
// its hemisphere's incoming radiance with translational gradients, inserted with the shared
// record store's radius rules; then every such sample's interpolated reflection, the glossy
// buffer irradiance caching's render pass reads. Owns its buffers; reports its statistics.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "methods/frame_scene.h"
#include "methods/glossy_cache.h"
#include "methods/glossy_placement.h"
#include "methods/irradiance_cache/irradiance_cache.h"
#include "methods/radiance_cache/brdf_tables.h"
#include "methods/records/record_store.h"

namespace rc {

struct RadianceCacheOptions {
    int order = 0;           // n_max of the BRDF tables and the records; 0: auto (RC_SH_MAX_ORDER)
    double max_error = 0.1;  // the BRDF tables' largest representation error (TVCG §4.1)
    int rays = 4096;  // hemisphere rays per record (M x N strata, N ~ 4 M; TVCG §6: 4000-6000)
    float accuracy = 0.35f;            // a (shared with irradiance caching's --accuracy)
    Spacing min_spacing{8.0f, false};  // bounds on a record's radius R
    Spacing max_spacing{64.0f, false};
    uint64_t seed = 0;
    int max_depth = 64;
    int rr_depth = 3;
    bool count_emission = false;      // count emitters the hemisphere rays see (tests)
    std::filesystem::path cache_in;   // radiance records to start from (--rc-cache-in)
    std::filesystem::path cache_out;  // where to save the radiance records (--rc-cache-out)
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
    double query_seconds = 0.0;
    double splat_seconds = 0.0;  // the glossy buffer
};

// Error (exit status 2) naming the option radiance caching cannot honour.
void check_radiance_cache_options(const RadianceCacheOptions& options);

// M x N strata with N ~ 4 M (course, "Incoming Radiance Computation") and M N close to `rays`.
void radiance_strata(int rays, int* m, int* n);

class RadianceCache final : public GlossyCache, private FrameBound {
   public:
    // Builds the frame's BRDF tables (the adaptive order, TVCG §4.1); reads options.cache_in.
    RadianceCache(const FrameScene& frame, const RadianceCacheOptions& options);

    Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                  const shared::CameraParams& camera,
                                                  const RadianceSource& diffuse) override;
    // (Saves the records to options.cache_out at the end.)
    std::vector<FilmLayer> layers() const override {
        return {{"rc-order", RC_CACHED_FILM_ORDER, 1}};
    }

    const RecordStore& store() const { return store_; }
    const RadianceCacheStats& stats() const { return stats_; }

   private:
    shared::RcParams record_params() const;
    // Records at `sites`, numbered from the store's size, inserted.
    void add_records(const std::vector<shared::RcQuery>& sites, const RadianceSource& diffuse);
    Kernel& cells_kernel(const RadianceSource& source);

    RadianceCacheOptions options_;
    RadianceCacheStats stats_;  // before tables_, which record their build time there
    BrdfTables tables_;
    int order_ = 0;
    int strata_m_ = 1;
    int strata_n_ = 1;
    RecordStore store_;
    Kernel queries_kernel_;
    Kernel project_kernel_;
    Kernel splat_kernel_;
    GlossyPlacement placement_;
    std::map<std::string, Kernel> cells_kernels_;  // by build options
};

}  // namespace rc
