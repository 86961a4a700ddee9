// Test kernel (tests/common/pixel_filter_test.cpp): camera sample positions drawn by the pixel
// sampler.
#include "common/kernel_range.h"
#include "common/pixel_sampler.h"

// out[i]: the image position of camera sample samples[i] of pixels[i] with seed (seed_lo, seed_hi).
RC_KERNEL void sampler_position_probe(uint begin, uint end, CameraParams camera, uint seed_lo,
                                      uint seed_hi, __global const uint* pixels,
                                      __global const uint* samples, __global float2* out) {
    RC_RANGE_ITEM(i);
    RngStream rng;
    out[i] = rc_camera_sample_position(&camera, seed_lo, seed_hi, pixels[i], samples[i], &rng);
}
