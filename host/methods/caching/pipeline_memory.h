// The device memory a frame of irradiance caching holds whatever its records
// (device/memory_need.h): the G-buffer, the splat sums and the film of the render pass, and the
// per-sample buffers of a glossy cache (radiance caching, SDRC) when one serves the specular lobes.
#pragma once

#include <cstddef>

#include "device/memory_need.h"
#include "methods/caching/cache_pipeline.h"
#include "scene/scene.h"

namespace rc {

// A glossy cache's buffers per camera sample: its queries (held while it places and splats its
// records) and its glossy samples (held until the render pass ends); 0, 0 without one.
struct GlossySampleBytes {
    size_t queries = 0;
    size_t glossy = 0;
    size_t fixed = 0;  // the buffers of its splat that do not grow with the samples
};

DeviceMemoryNeed cache_pipeline_device_need(const PipelineSettings& options, const Scene& scene,
                                            GlossySampleBytes glossy = {});

}  // namespace rc
