// Image textures: bilinear lookup with repeat wrapping.
#pragma once

#include "shared/types.h"

// The texel of texture `info` at integer coordinates, wrapped.
RC_FUNC float3 rc_texel(RC_GLOBAL const float4* texels, TextureInfo info, int x, int y) {
    const int width = info.width;
    const int height = info.height;
    x %= width;
    y %= height;
    x += x < 0 ? width : 0;
    y += y < 0 ? height : 0;
    return texels[info.first_texel + y * width + x].xyz;
}

// Linear RGB at texture coordinates uv ((0, 0) the bottom-left of the image, as in OBJ).
RC_FUNC float3 rc_texture_lookup(RC_GLOBAL const float4* texels, TextureInfo info, float2 uv) {
    const float x = (uv.x - floor(uv.x)) * (float)info.width - 0.5f;
    const float y = (1.0f - (uv.y - floor(uv.y))) * (float)info.height - 0.5f;
    const float x0 = floor(x);
    const float y0 = floor(y);
    const float fx = x - x0;
    const float fy = y - y0;
    const int ix = (int)x0;
    const int iy = (int)y0;
    return (1.0f - fy) * ((1.0f - fx) * rc_texel(texels, info, ix, iy) +
                          fx * rc_texel(texels, info, ix + 1, iy)) +
           fy * ((1.0f - fx) * rc_texel(texels, info, ix, iy + 1) +
                 fx * rc_texel(texels, info, ix + 1, iy + 1));
}
