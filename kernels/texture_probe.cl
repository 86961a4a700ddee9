// Test kernel (tests/scene/texture_test.cpp): texture lookups at given coordinates.
#include "common/kernel_range.h"
#include "common/texture.h"

RC_KERNEL void texture_lookup_probe(uint begin, uint end, TextureInfo info,
                                    __global const float4* texels, __global const float2* uvs,
                                    __global float4* out) {
    RC_RANGE_ITEM(i);
    out[i] = (float4)(rc_texture_lookup(texels, info, uvs[i]), 0.0f);
}
