// --light-samples: the light samples of next-event estimation at the camera's hit in the caching
// methods' render passes (ic, ivg, ivg-gather), combined with the one BRDF sample by the power
// heuristic with sample counts (kernels/common/path_radiance.h). Declared once here; each method
// that takes it lists kLightSamplesOption among its options, so the registry refuses it, by name,
// for the others (the path tracer: docs/path-tracer.md says why).
#pragma once

#include "util/cli.h"

namespace rc {

// The default, measured (docs/irradiance-caching.md, "Direct light: --light-samples"): at equal
// render time the direct light's error is lowest near 4 light samples for ic and ivg on the
// Cornell box and two-rooms.
constexpr int kDefaultLightSamples = 4;
// The most a render pass takes: beyond it the shadow rays cost more than further camera samples.
constexpr int kMaxLightSamples = 64;

extern const OptionSpec kLightSamplesOption;

// The option's value in [1, kMaxLightSamples] (the default when absent); Error (exit status 2)
// naming --light-samples otherwise.
int light_samples(const ParsedArguments& arguments);

}  // namespace rc
