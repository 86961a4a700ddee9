// Geometry of hit triangles.
#pragma once

#include "shared/types.h"

// The cross product of a triangle's edges, scaled by a power of two (exactly) when its squared
// length would leave float's normal range: edges shorter than about 1e-9.5 (a scene scaled by
// 1e-12) underflow it to 0, edges longer than about 4e9 overflow it to infinity. Within the range
// it is returned unscaled, so that normal-sized scenes compute bitwise what they did before.
RC_FUNC float3 rc_triangle_cross(RC_GLOBAL const Triangle* triangle, float* scale) {
    const float3 e1 = triangle->v1.xyz - triangle->v0.xyz;
    const float3 e2 = triangle->v2.xyz - triangle->v0.xyz;
    const float3 c = cross(e1, e2);
    const float length2 = dot(c, c);
    *scale = 1.0f;
    if (length2 >= FLT_MIN && length2 <= FLT_MAX) {
        return c;
    }
    const float largest = fmax(fabs(c.x), fmax(fabs(c.y), fabs(c.z)));
    if (!(largest > 0.0f) || !isfinite(largest)) {
        return c;
    }
    const int exponent = ilogb(largest);
    *scale = ldexp(1.0f, exponent);
    return ldexp(c, -exponent);  // largest component in [1, 2)
}

// Unit geometric normal of a triangle (right-handed winding v0, v1, v2).
RC_FUNC float3 rc_triangle_normal(RC_GLOBAL const Triangle* triangle) {
    float scale;
    return normalize(rc_triangle_cross(triangle, &scale));
}

// Area of a triangle.
RC_FUNC float rc_triangle_area(RC_GLOBAL const Triangle* triangle) {
    float scale;
    const float3 c = rc_triangle_cross(triangle, &scale);
    return 0.5f * length(c) * scale;
}
