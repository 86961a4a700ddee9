// What a --glossy SPEC (methods/caching/glossy_spec.h) makes of a render by irradiance caching: per
// frame the glossy caches it names, each serving its materials, in a GlossyMix; the programs they
// build and the device memory they hold beside irradiance caching's.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "device/program.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/caching/glossy_mix.h"
#include "methods/caching/glossy_spec.h"
#include "methods/caching/pipeline_memory.h"
#include "methods/frame_scene.h"

namespace rc {

// Error (exit status 2) naming a material of `spec` that `scene` lacks.
void check_glossy_spec(const GlossySpec& spec, const Scene& scene);

// The caches of `spec` for `frame` in the registry's order, each serving the materials `spec`
// gives it (every one with a specular lobe when `spec` names no material), their options the
// defaults with those `ic` shares; nullptr when `spec` names no cache (every lobe path traced).
std::unique_ptr<GlossyMix> make_glossy_mix(const FrameScene& frame, const PipelineSettings& ic,
                                           const GlossySpec& spec);

// The programs the caches of `spec` build beyond irradiance caching's (without duplicates).
std::vector<ProgramRequest> glossy_programs(const GlossySpec& spec);

// The caches' per-sample buffers at their peak (one cache's queries and glossy samples beside the
// buffers merged so far) and, into *excludes, what of theirs grows with their records.
GlossySampleBytes glossy_sample_bytes(const GlossySpec& spec, std::string* excludes);

}  // namespace rc
