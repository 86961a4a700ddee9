#include "methods/light_samples.h"

#include <string>

namespace rc {

const OptionSpec kLightSamplesOption =
    OptionSpec{"--light-samples", "", "N",
               "ic, ivg, ivg-gather: light samples of the direct light at the camera's hit, "
               "combined with one BRDF sample by multiple importance sampling (1 to " +
                   std::to_string(kMaxLightSamples) + "; default " +
                   std::to_string(kDefaultLightSamples) + ")"}
        .integers(1, kMaxLightSamples);

int light_samples(const ParsedArguments& arguments) {
    return static_cast<int>(arguments.integer(kLightSamplesOption.name, kDefaultLightSamples));
}

}  // namespace rc
