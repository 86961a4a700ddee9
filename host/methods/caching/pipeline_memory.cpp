#include "methods/caching/pipeline_memory.h"

#include <algorithm>

#include "methods/method.h"
#include "shared/film.h"
#include "shared/radiance_cache.h"

namespace rc {

DeviceMemoryNeed cache_pipeline_device_need(const PipelineSettings& options, const Scene& scene,
                                            GlossySampleBytes glossy) {
    const size_t pixels = image_pixels(options.width, options.height, scene);
    const size_t samples = pixels * static_cast<size_t>(std::max(options.spp, 1));
    const uint64_t gbuffer = buffer_bytes(samples, sizeof(shared::GBufferSample));
    const uint64_t glossy_samples = glossy.glossy > 0
                                        ? buffer_bytes(samples, glossy.glossy)
                                        : buffer_bytes(1, sizeof(shared::RcGlossySample));
    // CachePipeline::begin's G-buffer lives to the end; finish() makes the glossy buffer (or
    // its one-sample placeholder), then shade() the splat sums, the film and its counters.
    DeviceMemoryNeed shading;
    shading.add("gbuffer", gbuffer);
    shading.add("glossy samples", glossy_samples);
    shading.add("splat sums", buffer_bytes(samples, sizeof(shared::float4)));
    shading.add("film", buffer_bytes(pixels * RC_CACHED_FILM_SLOTS, sizeof(shared::float4)));
    shading.add("counters", buffer_bytes(3, sizeof(unsigned)));
    shading.excludes = "the cache records and their batches";
    if (glossy.queries == 0) {
        return shading;
    }
    // The glossy cache's splat: its queries beside its glossy samples, before the render pass.
    DeviceMemoryNeed splat;
    splat.add("gbuffer", gbuffer);
    splat.add("glossy queries", buffer_bytes(samples, glossy.queries));
    splat.add("glossy samples", glossy_samples);
    if (glossy.fixed > 0) {
        splat.add("glossy splat", glossy.fixed);
    }
    return peak_of(shading, splat);
}

}  // namespace rc
