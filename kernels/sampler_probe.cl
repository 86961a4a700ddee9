// Test kernel (tests/common/pixel_filter_test.cpp): camera sample positions drawn by the pixel
// sampler.
#include "common/pixel_sampler.h"

// out[i]: the image position of camera sample samples[i] of pixels[i] with seed (seed_lo, seed_hi).
__kernel void sampler_position_probe(uint begin, uint end, CameraParams camera, uint seed_lo,
                                     uint seed_hi, __global const uint* pixels,
                                     __global const uint* samples, __global float2* out) {
    const uint i = begin + (uint)get_global_id(0);
    if (i >= end) {
        return;
    }
    RngStream rng;
    out[i] = rc_camera_sample_position(&camera, seed_lo, seed_hi, pixels[i], samples[i], &rng);
}
