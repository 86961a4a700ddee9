// Geometry of hit triangles.
#pragma once

#include "shared/types.h"

// Unit geometric normal of a triangle (right-handed winding v0, v1, v2).
RC_FUNC float3 rc_triangle_normal(RC_GLOBAL const Triangle* triangle) {
    const float3 e1 = triangle->v1.xyz - triangle->v0.xyz;
    const float3 e2 = triangle->v2.xyz - triangle->v0.xyz;
    return normalize(cross(e1, e2));
}

// Area of a triangle.
RC_FUNC float rc_triangle_area(RC_GLOBAL const Triangle* triangle) {
    const float3 e1 = triangle->v1.xyz - triangle->v0.xyz;
    const float3 e2 = triangle->v2.xyz - triangle->v0.xyz;
    return 0.5f * length(cross(e1, e2));
}
