// What the glossy caches' methods (`rc`, `sdrc`) share as registered methods: their layers, and one
// frame rendered by irradiance caching with the cache serving the specular lobes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "methods/caching/cache_pipeline.h"
#include "methods/caching/glossy_cache.h"
#include "methods/caching/record_passes.h"
#include "methods/method.h"

namespace rc {

// Irradiance caching's layers, glossy-indirect and the cache's own `layer`.
std::vector<std::string> glossy_method_aovs(const std::string& layer);

// What a glossy cache's records take from the irradiance records of the same render: the
// accuracy a, the bounds on a record's radius and the shared settings.
template <class GlossyOptions>
void share_record_settings(const PipelineSettings& ic, GlossyOptions* glossy) {
    glossy->accuracy = ic.accuracy;
    glossy->min_spacing = ic.min_spacing;
    glossy->max_spacing = ic.max_spacing;
    glossy->share(ic);
}

// A glossy cache of type Cache for `frame` (GlossyCacheEntry::create,
// methods/caching/glossy_caches.h): its options `Options` at their defaults with the settings it
// takes from the irradiance records' (share_record_settings), serving the materials `served` marks.
template <class Cache, class Options>
std::unique_ptr<GlossyCache> make_glossy_cache(const FrameScene& frame, const PipelineSettings& ic,
                                               const ServedMaterials& served) {
    Options options;
    share_record_settings(ic, &options);
    options.materials = served;
    return std::make_unique<Cache>(frame, options);
}

// One frame by irradiance caching with `glossy` serving the specular lobes, in one pass or by
// `time` (records/record_passes.h): the image, its spp, the rays of both caches, non-finite
// samples, irradiance caching's statistics and the caches' seconds into the result, `finish`
// adding the glossy cache's statistics to each pass's; irradiance caching's statistics of the
// last pass into *stats.
FrameResult render_with_glossy_cache(const FrameScene& frame, const PipelineSettings& options,
                                     GlossyCache& glossy, double time, const FrameHooks& hooks,
                                     const RecordPassFinish& finish, PipelineStats* stats);

}  // namespace rc
