// The settings every method's options share: the image size, camera samples per pixel, the seed
// and the path depth limits. Each method's options struct derives from it, so the render sets
// them once for all (MethodSettings::apply_to) instead of copying them field by field.
#pragma once

#include <cstdint>

namespace rc {

// A window of the image's pixels: columns x0 .. x1 - 1, rows y0 .. y1 - 1 (--crop). Empty (x1 ==
// 0): the whole image.
struct PixelWindow {
    int x0 = 0;
    int x1 = 0;
    int y0 = 0;
    int y1 = 0;

    bool empty() const { return x1 <= x0 || y1 <= y0; }
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};

struct SharedSettings {
    int width = 0;  // 0: the scene camera's
    int height = 0;
    int spp = 16;  // camera samples per pixel
    // The index of the first camera sample of each pixel (--sample-range S0:S1 renders samples
    // S0 .. S0 + spp - 1: those a single render of S0 + spp samples would draw).
    int first_sample = 0;
    PixelWindow crop;  // --crop: the pixels rendered (empty: all)
    uint64_t seed = 0;
    int max_depth = 64;
    int rr_depth = 3;

    // These settings of `other` (the options of another record cache of the same render).
    void share(const SharedSettings& other) { *this = other; }
};

// The seed as the kernels take it, in two 32-bit words (seed_lo, seed_hi of any parameter struct).
template <class Params>
void set_kernel_seed(uint64_t seed, Params* params) {
    params->seed_lo = static_cast<unsigned>(seed);
    params->seed_hi = static_cast<unsigned>(seed >> 32);
}

// The seed and the path depth limits of `settings` (any struct with seed, max_depth and rr_depth)
// into a kernel parameter struct with the fields of those names.
template <class Settings, class Params>
void set_kernel_path_settings(const Settings& settings, Params* params) {
    set_kernel_seed(settings.seed, params);
    params->max_depth = settings.max_depth;
    params->rr_depth = settings.rr_depth;
}

}  // namespace rc
