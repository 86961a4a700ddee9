// The spherical triangle a planar triangle subtends from a point: its solid angle and directions
// distributed uniformly in it (Arvo, "Stratified Sampling of Spherical Triangles", SIGGRAPH 1995).
// Vertices are unit vectors a, b, c from the point; the triangle's angle at a is alpha and the
// arc opposite c (from a to b) has length c_arc, so cos(c_arc) = a.b.
#pragma once

#include "common/math.h"
#include "shared/types.h"

// a . (b x c) for unit a, b, c, from the edges b - a and c - a: exact in exact arithmetic, and
// without the cancellation of b x c for a small triangle (nearly parallel vertices).
RC_FUNC float rc_spherical_triple(float3 a, float3 b, float3 c) {
    return dot(a, cross(b - a, c - a));
}

// Solid angle of the spherical triangle abc (unit vertices): Van Oosterom and Strackee, "The
// Solid Angle of a Plane Triangle", IEEE TBME 30(2), 1983: tan(Omega / 2) = |a.(b x c)| /
// (1 + a.b + b.c + c.a). atan2 keeps it right past Omega = pi and accurate for small triangles,
// where Girard's alpha + beta + gamma - pi cancels.
RC_FUNC float rc_spherical_triangle_solid_angle(float3 a, float3 b, float3 c) {
    const float denominator = 1.0f + dot(a, b) + dot(b, c) + dot(c, a);
    return 2.0f * atan2(fabs(rc_spherical_triple(a, b, c)), denominator);
}

// The angle at vertex a (unit) between the arcs ab and ac, as its sine and cosine (returns the
// sine): the angle between the planes a x b and a x c, whose cross product is a (a.(b x c)) (Arvo
// 1995, Figure 1's alpha). The planes' normals are taken as a x (b - a) and a x (c - a), which are
// exact for nearby vertices; sine and cosine come from the two products without a trigonometric
// call (alpha = atan2(|a.(b x c)|, (a x b).(a x c))).
RC_FUNC float rc_spherical_angle_sin_cos(float3 a, float3 b, float3 c, float* cos_alpha) {
    const float y = fabs(rc_spherical_triple(a, b, c));
    const float x = dot(cross(a, b - a), cross(a, c - a));
    const float r = sqrt(x * x + y * y);  // |x|, |y| <= 4 for unit a, b, c: no overflow
    if (r <= 0.0f) {
        *cos_alpha = 1.0f;
        return 0.0f;
    }
    *cos_alpha = x / r;
    return y / r;
}

// The unit tangent at unit u of the great arc from u towards unit v: v - (v.u) u normalised,
// computed as (v - u) + (1 - u.v) u with 1 - u.v = |v - u|^2 / 2 (no cancellation for nearby u,
// v); zero when v = u.
RC_FUNC float3 rc_arc_tangent(float3 u, float3 v) {
    const float3 d = v - u;
    const float3 w = d + (0.5f * dot(d, d)) * u;
    const float length_w = length(w);
    return length_w > 0.0f ? w / length_w : (float3)(0.0f);
}

// The point at arc length theta from unit u towards tangent t, given 1 - cos(theta) = w in
// [0, 2]: (1 - w) u + sqrt(w (2 - w)) t.
RC_FUNC float3 rc_arc_point(float3 u, float3 t, float w) {
    return (1.0f - w) * u + sqrt(fmax(0.0f, w * (2.0f - w))) * t;
}

// A direction uniform in solid angle over the spherical triangle abc (unit vertices) of solid
// angle `area`, from (u1, u2) in [0, 1)^2 (Arvo 1995, "The Sampling Algorithm", two inversions):
// stage 1 picks the sub-triangle a b c' of area A' = u1 * area, c' on the arc ac; stage 2 picks
// the point P on the arc b c' whose cosine to b, z, is uniform in [b.c', 1].
// Arvo gives the cosine q of the arc a c' as ((v t - u s) cos(alpha) - v) / ((v s + u t)
// sin(alpha)), s = sin(A' - alpha), t = cos(A' - alpha), u = t - cos(alpha), v = s + sin(alpha)
// cos(c_arc). That loses float precision for small triangles (q near 1, 1 - a.b near 0): the same
// quantity is computed here as 1 - q = (1 + cos c_arc) sin^2(A'/2) / (sin^2(A'/2) - sin(A' -
// alpha) sin(alpha) sin^2(c_arc/2)), from Arvo's expression with t cos(alpha) - s sin(alpha) =
// cos(A') (algebra in docs/path-tracer.md), with sin^2(c_arc/2) = |b - a|^2 / 4, and likewise
// 1 - z = u2 |c' - b|^2 / 2.
RC_FUNC float3 rc_sample_spherical_triangle(float3 a, float3 b, float3 c, float area, float u1,
                                            float u2) {
    float cos_alpha;
    const float sin_alpha = rc_spherical_angle_sin_cos(a, b, c, &cos_alpha);
    const float3 ab = b - a;
    const float sin2_half_c = 0.25f * dot(ab, ab);  // sin^2(c_arc / 2)
    // Stage 1: 1 - cos(arc a c') and c'. sin(A' - alpha) = sin A' cos alpha - cos A' sin alpha,
    // sin A' and cos A' from the half angle's sine and cosine (one argument reduction).
    float cos_half_sub;
    const float sin_half_sub = sincos(0.5f * u1 * area, &cos_half_sub);
    const float sin2_half_sub = sin_half_sub * sin_half_sub;
    const float sin_sub = 2.0f * sin_half_sub * cos_half_sub;
    const float cos_sub = 1.0f - 2.0f * sin2_half_sub;
    const float sin_sub_minus_alpha = sin_sub * cos_alpha - cos_sub * sin_alpha;
    const float denominator = sin2_half_sub - sin_sub_minus_alpha * sin_alpha * sin2_half_c;
    const float one_minus_q =
        denominator > 0.0f
            ? clamp((2.0f - 2.0f * sin2_half_c) * sin2_half_sub / denominator, 0.0f, 2.0f)
            : 0.0f;
    const float3 c_sub = normalize(rc_arc_point(a, rc_arc_tangent(a, c), one_minus_q));
    // Stage 2: 1 - z and P on the arc from b to c'.
    const float3 bc = c_sub - b;
    const float one_minus_z = u2 * 0.5f * dot(bc, bc);
    return normalize(rc_arc_point(b, rc_arc_tangent(b, c_sub), one_minus_z));
}
