// What `radcache devices` asks of each device (host/device/device_features.h): which of the
// extensions radcache's kernels use its OpenCL C compiler defines, and a launch long enough for
// its profiling events to measure.

#include "common/kernel_range.h"

// Bit 0: cl_khr_fp64 (ray_triangle.h's exact edge functions); bit 1: cl_khr_int64_base_atomics
// (compat.h's 64-bit atomic addition of the irradiance vector grid's sums).
RC_KERNEL void device_features(uint begin, uint end, __global int* out) {
    if (begin + get_global_id(0) != 0u || end == 0u) {
        return;
    }
    int features = 0;
#ifdef cl_khr_fp64
    features |= 1;
#endif
#ifdef cl_khr_int64_base_atomics
    features |= 2;
#endif
    out[0] = features;
}

// A few milliseconds of arithmetic per launch of 2^16 items.
RC_KERNEL void device_busy(uint begin, uint end, __global float* out) {
    RC_RANGE_ITEM(i);
    float x = (float)i * 1e-6f;
    for (int k = 0; k < 2048; ++k) {
        x = x * 0.999f + 0.001f;
    }
    out[i] = x;
}

// Whether the device ends a work item's loops early (Mesa's llvmpipe stops every loop of an
// invocation once their iterations together reach 65535): `iterations` steps of the LCG
// x <- 1664525 x + 1013904223 (mod 2^32) from `seed`, which no compiler reduces to a closed form,
// into out[0]; the host compares it with its own steps (host/device/device_features.cpp).
RC_KERNEL void device_loop_cap(uint begin, uint end, uint iterations, uint seed,
                               __global uint* out) {
    if (begin + get_global_id(0) != 0u || end == 0u) {
        return;
    }
    uint x = seed;
    for (uint q = 0; q < iterations; ++q) {
        x = x * 1664525u + 1013904223u;
    }
    out[0] = x;
}
