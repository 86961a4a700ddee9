// The glossy caches a render by irradiance caching can serve specular lobes with (`--method ic
// --glossy`, methods/caching/glossy_spec.h; the caches of `--method rc` and `--method sdrc`),
// listed in one place, glossy_caches.cpp; each entry is defined in its method's folder. A cache is
// made per frame from the irradiance records' options (its own at their defaults, with the record
// settings it shares, share_record_settings) and the set of materials it serves.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "device/program.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/caching/glossy_cache.h"
#include "methods/caching/pipeline_memory.h"
#include "methods/frame_scene.h"

namespace rc {

struct GlossyCacheEntry {
    std::string name;       // --glossy's name of it ("rc", "sdrc")
    std::string layer;      // its own AOV layer (GlossyCache::layers)
    std::string stats_key;  // its statistics' key in a frame's statistics
    // Its cache for `frame`, serving the materials `served` marks (per scene material; empty:
    // every material with a specular lobe), its options the defaults with those `ic` shares.
    std::function<std::unique_ptr<GlossyCache>(const FrameScene& frame, const PipelineSettings& ic,
                                               const ServedMaterials& served)>
        create;
    std::vector<ProgramRequest> programs;  // beyond irradiance caching's (Method::programs)
    GlossySampleBytes bytes;               // its per-sample buffers (Method::device_memory_need)
    std::string excludes;                  // what of its memory grows with its records
};

const std::vector<GlossyCacheEntry>& glossy_cache_registry();
// The entry named `name`, or nullptr.
const GlossyCacheEntry* find_glossy_cache(const std::string& name);
// "rc, sdrc".
std::string glossy_cache_names();

}  // namespace rc
