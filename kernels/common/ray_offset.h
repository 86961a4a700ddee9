// Origins of secondary rays, offset off the surface they leave: Wächter and Binder, "A Fast and
// Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, ch. 6. The offset is a fixed
// number of float ulps along the normal (so it scales with the magnitude of the position), and a
// small absolute step near the origin where ulps are tiny. No scene-dependent epsilon.
#pragma once

#include "shared/types.h"

// p: a point on the surface; n: the unit geometric normal on the side the new ray leaves to.
RC_FUNC float3 rc_offset_ray_origin(float3 p, float3 n) {
    const float kOriginBand = 1.0f / 32.0f;
    const float kFloatScale = 1.0f / 65536.0f;
    const float kIntScale = 256.0f;
    const int3 ulps = convert_int3(kIntScale * n);
    const int3 bits = as_int3(p);
    const float3 moved = as_float3(bits + select(ulps, -ulps, p < 0.0f));
    return select(moved, p + kFloatScale * n, fabs(p) < kOriginBand);
}

// The origin of a ray leaving point p of `triangle`. The ray/triangle test's error in the
// distance to the plane grows with the vertices' magnitude, not the hit point's (a hit near the
// origin on a triangle with kilometre-sized coordinates), so p first moves along n by 32 ulps of
// the largest vertex coordinate (pbrt-v3 §3.9 bounds these errors by small multiples of
// epsilon times the vertex magnitudes), then by Wächter and Binder's offset.
RC_FUNC float3 rc_offset_surface_origin(float3 p, float3 n, RC_GLOBAL const Triangle* triangle) {
    const float3 magnitude =
        fmax(fabs(triangle->v0.xyz), fmax(fabs(triangle->v1.xyz), fabs(triangle->v2.xyz)));
    const float scale = fmax(magnitude.x, fmax(magnitude.y, magnitude.z));
    const float kErrorUlps = 32.0f * 5.9604645e-8f;  // 32 * 2^-24
    return rc_offset_ray_origin(p + (kErrorUlps * scale) * n, n);
}
