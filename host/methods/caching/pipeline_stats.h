// Irradiance caching's figures in a frame's statistics (`--method ic`, and the diffuse records
// of `--method rc`).
#pragma once

#include <nlohmann/json.hpp>

#include "methods/caching/cache_pipeline.h"

namespace rc {

// Placement passes, records per level, rays, cache bytes and phase times into *out.
void add_irradiance_cache_stats(const PipelineStats& stats, const PipelineSettings& options,
                                nlohmann::json* out);

}  // namespace rc
