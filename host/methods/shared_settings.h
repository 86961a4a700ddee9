// The settings every method's options share: the image size, camera samples per pixel, the seed
// and the path depth limits. Each method's options struct derives from it, so the render sets
// them once for all (MethodSettings::apply_to) instead of copying them field by field.
#pragma once

#include <cstdint>

namespace rc {

struct SharedSettings {
    int width = 0;  // 0: the scene camera's
    int height = 0;
    int spp = 16;  // camera samples per pixel
    uint64_t seed = 0;
    int max_depth = 64;
    int rr_depth = 3;

    // These settings of `other` (the options of another record cache of the same render).
    void share(const SharedSettings& other) { *this = other; }
};

}  // namespace rc
