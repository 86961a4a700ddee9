// The parabolic parametrization of the hemisphere of outgoing directions (Heidrich and Seidel,
// "Realistic, Hardware-Accelerated Shading and Lighting", SIGGRAPH 1999; TVCG 2005 §4.1 samples
// the BRDF tables on it): direction d, d.z >= 0, is the point p = (d.x, d.y) / (1 + d.z) of the
// unit disk, and back d = (2 p.x, 2 p.y, 1 - |p|^2) / (1 + |p|^2). A table covers the square
// [-1, 1]^2 in resolution^2 texels; texels whose centre lies outside the disk hold the rim's
// direction (the horizon), so bilinear lookups near grazing angles have four neighbours.
#pragma once

#include "common/math.h"

RC_FUNC float2 rc_parabolic_from_direction(float3 d) { return (float2)(d.x, d.y) / (1.0f + d.z); }

// The direction of p, p outside the unit disk taken to the rim.
RC_FUNC float3 rc_parabolic_to_direction(float2 p) {
    const float r2 = dot(p, p);
    if (r2 >= 1.0f) {
        const float2 rim = p / sqrt(r2);
        return (float3)(rim.x, rim.y, 0.0f);
    }
    return (float3)(2.0f * p.x, 2.0f * p.y, 1.0f - r2) / (1.0f + r2);
}

// The centre of texel (i, j).
RC_FUNC float2 rc_parabolic_texel_centre(int i, int j, int resolution) {
    const float size = 2.0f / (float)resolution;
    return (float2)(-1.0f + ((float)i + 0.5f) * size, -1.0f + ((float)j + 0.5f) * size);
}
