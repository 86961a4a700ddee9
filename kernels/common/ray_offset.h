// Origins of secondary rays, offset off the surface they leave: Wächter and Binder, "A Fast and
// Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, ch. 6. The offset is a fixed
// number of float ulps along the normal (so it scales with the magnitude of the position), and a
// small step near the origin where ulps are tiny. That step and the band where it applies are
// 1/65536 and 1/32 of the triangle's unit (rc_triangle_unit): 1 for every triangle reaching 0.5
// from the origin, so that a scene scaled by a power of two offsets its rays by the same factor.
#pragma once

#include "shared/types.h"

// p: a point on the surface; n: the unit geometric normal on the side the new ray leaves to;
// unit: the length the near-origin band and step are fractions of (a power of two, at most 1).
RC_FUNC float3 rc_offset_ray_origin_in(float3 p, float3 n, float unit) {
    const float kOriginBand = 1.0f / 32.0f;
    const float kFloatScale = 1.0f / 65536.0f;
    const float kIntScale = 256.0f;
    const int3 ulps = convert_int3(kIntScale * n);
    const int3 bits = as_int3(p);
    const float3 moved = as_float3(bits + select(ulps, -ulps, p < 0.0f));
    return select(moved, p + (kFloatScale * unit) * n, fabs(p) < kOriginBand * unit);
}

// The largest magnitude of a triangle's vertex coordinates.
RC_FUNC float rc_triangle_magnitude(RC_GLOBAL const Triangle* triangle) {
    const float3 magnitude =
        fmax(fabs(triangle->v0.xyz), fmax(fabs(triangle->v1.xyz), fabs(triangle->v2.xyz)));
    return fmax(magnitude.x, fmax(magnitude.y, magnitude.z));
}

// The triangle's unit: the smallest power of two at least its magnitude, at most 1 (exact).
RC_FUNC float rc_triangle_unit(float magnitude) {
    int exponent = 0;
    frexp(magnitude, &exponent);
    return exponent >= 0 ? 1.0f : ldexp(1.0f, exponent);
}

// The origin of a ray leaving point p of `triangle` (or the end of a shadow ray on it), with
// the triangle's unit.
RC_FUNC float3 rc_offset_ray_origin(float3 p, float3 n, RC_GLOBAL const Triangle* triangle) {
    return rc_offset_ray_origin_in(p, n, rc_triangle_unit(rc_triangle_magnitude(triangle)));
}

// The origin of a ray leaving point p of `triangle`. The ray/triangle test's error in the
// distance to the plane grows with the vertices' magnitude, not the hit point's (a hit near the
// origin on a triangle with kilometre-sized coordinates), so p first moves along n by 32 ulps of
// the largest vertex coordinate (pbrt-v3 §3.9 bounds these errors by small multiples of
// epsilon times the vertex magnitudes), then by Wächter and Binder's offset.
RC_FUNC float3 rc_offset_surface_origin(float3 p, float3 n, RC_GLOBAL const Triangle* triangle) {
    const float scale = rc_triangle_magnitude(triangle);
    const float kErrorUlps = 32.0f * 5.9604645e-8f;  // 32 * 2^-24
    return rc_offset_ray_origin_in(p + (kErrorUlps * scale) * n, n, rc_triangle_unit(scale));
}
