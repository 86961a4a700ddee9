// Irradiance caching on the device (DESIGN.md §6.2; `radcache render --method ic`): a G-buffer
// of camera samples, records placed coarse to fine where the cache does not yet cover the
// image, computed by stratified hemisphere sampling with gradients, inserted on the host with
// gradient-limited, neighbor-clamped radii into a world-space grid, and a shading pass that
// interpolates them. Owns its buffers; reports its statistics.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bvh/device_bvh.h"
#include "device/context.h"
#include "image/image.h"
#include "methods/irradiance_records.h"
#include "scene/device_scene.h"
#include "scene/scene.h"

namespace rc {

// A record spacing: pixels (of the projected pixel footprint) or scene units.
struct Spacing {
    float value = 0.0f;
    bool world = false;
};
// "4", "4px" (pixels) or "0.5u" (scene units); Error (exit status 2) naming `option` otherwise.
Spacing parse_spacing(const std::string& text, const std::string& option);

struct IrradianceCacheOptions {
    int width = 0;  // 0: the scene camera's
    int height = 0;
    int spp = 4;  // camera samples per pixel
    uint64_t seed = 0;
    int max_depth = 64;
    int rr_depth = 3;
    float accuracy = 0.25f;            // a: records influence points within a R
    int rays = 512;                    // hemisphere rays per record (M x N strata, N ~ pi M)
    Spacing min_spacing{2.0f, false};  // bounds on a record's influence radius a R
    Spacing max_spacing{32.0f, false};
    int bounces = 1;                  // 1: hemisphere rays path-trace what lies beyond
    std::filesystem::path cache_in;   // records to start from
    std::filesystem::path cache_out;  // where to save the records
};

struct IrradianceCacheStats {
    std::vector<int> level_strides;     // pixel stride of each placement pass
    std::vector<size_t> level_records;  // records created by each pass
    size_t records = 0;                 // in the cache at the end (loaded ones included)
    size_t loaded_records = 0;
    int strata_m = 0;
    int strata_n = 0;
    uint64_t record_rays = 0;   // rays traced for records (hemisphere rays and their paths)
    uint64_t shading_rays = 0;  // rays traced by the shading pass
    double gbuffer_seconds = 0.0;
    double placement_seconds = 0.0;  // coverage queries and candidate selection
    double record_seconds = 0.0;     // hemisphere sampling and reduction
    double insertion_seconds = 0.0;  // host insertion, device records and grid
    double shading_seconds = 0.0;
    size_t cache_bytes = 0;  // records and grid on the device
    uint64_t nonfinite_samples = 0;
    int64_t first_nonfinite_pixel = -1;
};

// The layers of an irradiance-cached image, in channel order: beauty (R, G, B), direct, indirect
// (3 channels each), albedo, normal, coverage (1 channel: the sum of record weights), records
// (record centres red, influence borders green).
extern const char* const kIrradianceCacheAovs[7];

// Where a record is to be computed.
struct RecordSite {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 origin{0.0f};  // the surface point offset for leaving rays
    float r_min = 0.0f;
    float r_max = 0.0f;
};

// How records sample their hemisphere.
struct RecordSampling {
    int m = 13;  // polar strata
    int n = 39;  // azimuthal strata
    int max_depth = 64;
    int rr_depth = 3;
    uint64_t seed = 0;
    bool include_emission = false;  // count emitters the hemisphere rays see (tests)
};

// M x N strata with N ~ pi M and M N close to `rays`.
RecordSampling strata_for(int rays);

class IrradianceCache {
   public:
    IrradianceCache(Context& context, const Scene& scene, const DeviceBvh& bvh,
                    const DeviceScene& device_scene);

    Image render(const IrradianceCacheOptions& options, IrradianceCacheStats* stats = nullptr);

    // The record kernels on arbitrary sites; `first_index` numbers them (their random streams).
    std::vector<CacheRecord> compute_records(const std::vector<RecordSite>& sites,
                                             uint32_t first_index, const RecordSampling& sampling,
                                             uint64_t* rays = nullptr);

    // (sum w E', sum w) of `store`'s records at G-buffer-like query points.
    std::vector<shared::float4> gather(const RecordStore& store,
                                       const std::vector<shared::GBufferSample>& queries);

    const RecordStore& store() const { return store_; }

   private:
    Context& context_;
    const Scene& scene_;
    const DeviceBvh& bvh_;
    const DeviceScene& device_scene_;
    Kernel gbuffer_kernel_;
    Kernel cells_kernel_;
    Kernel reduce_kernel_;
    Kernel gather_kernel_;
    Kernel shade_kernel_;
    RecordStore store_{0.25f};
};

}  // namespace rc
