#include "methods/light_samples.h"

namespace rc {

const char* const kLightSamplesHelp =
    "light samples of the direct light at the camera's hit, combined with one BRDF sample by "
    "multiple importance sampling";

}  // namespace rc
