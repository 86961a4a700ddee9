// Irradiance caching with a glossy cache (RadianceCache, SdrcCache) filling its glossy buffer: how
// the glossy caches' method tests (rc_method_test, sdrc_method_test) render.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "image/image.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/sdrc/sdrc_cache.h"
#include "test_support.h"

namespace rc::test {

// Irradiance caching's options for a size x size image, one cache level of `rays` hemisphere rays
// (the diffuse records are not what these tests measure), no records overlay.
PipelineSettings glossy_ic_options(int size, int spp, uint64_t seed, int rays = 256);

// The indirect layer of `device`'s scene path traced at size x size, 1024 samples per pixel (seed
// 11): the reference the glossy caches and the path-traced lobe are measured against.
Image path_traced_indirect(DeviceFrame& device, int size);

template <class Cache>
struct GlossyRender {
    Image image;
    std::decay_t<decltype(std::declval<const Cache&>().stats())> stats;  // the glossy cache's
};

// The image of irradiance caching `ic` whose glossy buffer a radiance cache (rc) or an SDRC cache
// of `options` (its seed ic's) fills, and that cache's stats.
using RcRender = GlossyRender<RadianceCache>;
RcRender render_rc(DeviceFrame& device, PipelineSettings ic, RadianceCacheOptions options = {});
using SdrcRender = GlossyRender<SdrcCache>;
SdrcRender render_sdrc(DeviceFrame& device, PipelineSettings ic, SdrcOptions options = {});

// The indirect light on the Phong sphere (phong_sphere_scene's, sphere_mask of the albedo layer of
// `glossy_image`) against `reference`: relMSE of `glossy_image`, rendered with a glossy cache, and
// of irradiance caching `ic` alone, which path traces the lobe (the same diffuse records).
struct SphereErrors {
    double glossy = 0.0;
    double monte_carlo = 0.0;
    size_t pixels = 0;  // the sphere's
};
SphereErrors sphere_errors(DeviceFrame& device, const PipelineSettings& ic,
                           const Image& glossy_image, const Image& reference);

}  // namespace rc::test
