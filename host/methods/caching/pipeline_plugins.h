// What a caching method plugs into the record-caching pipeline (CachePipeline,
// cache_pipeline.h), apart from its settings: where the records' hemisphere rays read the light
// beyond their hits, the lobe caches that serve the specular lobes at camera samples, an observer
// of the record batches, and the primitives that get no deeper-level record. The settings
// (PipelineSettings) are values a command line gives; these are objects a method owns.
#pragma once

#include <cstdint>
#include <vector>

namespace rc {

class RadianceSource;       // methods/radiance_source.h
class GlossyCache;          // methods/caching/glossy_cache.h
class RecordBatchObserver;  // methods/caching/cache_pipeline.h

struct PipelinePlugins {
    // Where the last cache level's hemisphere rays read the radiance beyond their hits
    // (--ic-ivg: the irradiance vector grid; one cache level only); null: path-traced
    // continuation.
    const RadianceSource* beyond = nullptr;
    // Where the render pass reads the specular lobes' indirect light at camera samples (radiance
    // caching, SDRC, `ic --glossy`) instead of path tracing them; its hemisphere rays read the
    // pipeline's first level. Adds the layer glossy-indirect and the cache's own layers.
    GlossyCache* lobes = nullptr;
    // Shown every batch of records the kernels compute, before insertion (temporal caching
    // reprojects their hemisphere samples).
    RecordBatchObserver* observer = nullptr;
    // Per primitive (empty: none): nonzero where hemisphere hits get no deeper-level record and
    // path-trace the diffuse lobe beyond instead, as a hit no record covers does (temporal
    // caching: records on moving triangles serve one frame, not worth their rays).
    std::vector<uint8_t> uncached_primitives;
};

}  // namespace rc
