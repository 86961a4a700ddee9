// --light-samples: the light samples of next-event estimation at the camera's hit in the caching
// methods' render passes (ic, ivg, ivg-gather), combined with the one BRDF sample by the power
// heuristic with sample counts (kernels/common/path_radiance.h). Declared once here; each method
// that takes it adds it to its option table (add_light_samples_option), so the registry refuses
// it, by name, for the others (the path tracer: docs/path-tracer.md says why).
#pragma once

#include "util/cli.h"
#include "util/option_table.h"

namespace rc {

// The default, measured (docs/irradiance-caching.md, "Direct light: --light-samples"): at equal
// render time the direct light's error is lowest near 4 light samples for ic and ivg on the
// Cornell box and two-rooms.
constexpr int kDefaultLightSamples = 4;
// The most a render pass takes: beyond it the shadow rays cost more than further camera samples.
constexpr int kMaxLightSamples = 64;

extern const char* const kLightSamplesHelp;

// --light-samples into `field` of a method's options table (its default: the field's).
template <class T>
OptionTable<T>& add_light_samples_option(OptionTable<T>& table, int T::*field) {
    return table.integer("--light-samples", "N", field, 1, kMaxLightSamples, kLightSamplesHelp)
        .knob(KnobDirection::kIncrease);
}

}  // namespace rc
