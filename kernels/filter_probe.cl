// Test kernel (tests/common/pixel_filter_test.cpp): camera sample positions drawn from the pixel
// filter.
#include "common/kernel_range.h"
#include "common/pixel_filter.h"

// out[i]: the position of the sample of pixels[i] drawn with uvs[i].
RC_KERNEL void filter_position_probe(uint begin, uint end, CameraParams camera,
                                     __global const uint* pixels, __global const float2* uvs,
                                     __global float2* out) {
    RC_RANGE_ITEM(i);
    out[i] = rc_filter_sample_position(&camera, pixels[i], uvs[i].x, uvs[i].y);
}
