// A cache of the glossy lobes' indirect light at the camera samples (radiance caching, DESIGN.md
// §6.4) that irradiance caching's render pass reads instead of path tracing those lobes: the
// glossy buffer, one RcGlossySample per camera sample (kernels/shared/radiance_cache.h).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "device/buffer.h"
#include "image/film.h"
#include "methods/radiance_source.h"
#include "shared/film.h"
#include "shared/radiance_cache.h"
#include "shared/types.h"

namespace rc {

// Per scene material: nonzero where a glossy cache serves its specular lobe; empty: every material
// (a cache's camera samples on the others are left to path tracing, glossy entries of order -1).
using ServedMaterials = std::vector<uint8_t>;

class GlossyCache {
   public:
    virtual ~GlossyCache() = default;
    // The glossy buffer of the camera samples of `camera`'s image, entry pixel * spp + s
    // (params: width, height, camera_spp, seed, depth limits, as the render pass traces them),
    // once the irradiance records are placed; `diffuse`: the radiance the cache's hemisphere rays
    // read beyond their hits.
    virtual Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                          const shared::CameraParams& camera,
                                                          const RadianceSource& diffuse) = 0;
    // The cache's own layers of the render pass's film (kernels/shared/film.h) beside
    // glossy-indirect.
    virtual std::vector<FilmLayer> layers() const = 0;
    // The rays its records (and their lookups' misses) have traced since it was made, and the
    // seconds their placement and computation took (the cache's share of a render by time).
    virtual uint64_t rays() const = 0;
    virtual double record_seconds() const = 0;
    // Its statistics of the frame so far (null: none).
    virtual nlohmann::json statistics() const { return nullptr; }
};

}  // namespace rc
