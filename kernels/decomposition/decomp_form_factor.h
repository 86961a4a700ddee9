// The form factor FF(t) of a triangle to a differential area at a shading point (the paper, §5:
// "the analytical polygon to point form factor formula given by [Hottel and Sarofim 1967]"), the
// triangle taken as wholly visible.
#pragma once

#include "common/math.h"

// The largest polygon clipping a triangle by one plane makes.
#define RC_DECOMP_CLIPPED_VERTICES 4

// The triangle (v0, v1, v2) clipped to the half-space dot(x - p, n) >= 0 above the shading
// point's tangent plane (the part below cannot light p; the closed form holds for a polygon
// above the plane only): its vertices into out, their count returned (0, 3 or 4).
RC_FUNC int rc_decomp_clip_to_horizon(float3 p, float3 n, float3 v0, float3 v1, float3 v2,
                                      float3 out[RC_DECOMP_CLIPPED_VERTICES]) {
    const float3 v[3] = {v0, v1, v2};
    const float h[3] = {dot(v0 - p, n), dot(v1 - p, n), dot(v2 - p, n)};
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (h[i] >= 0.0f) {
            out[count++] = v[i];
        }
        if ((h[i] >= 0.0f) != (h[j] >= 0.0f)) {
            // The edge crosses the plane: the crossing point (Sutherland-Hodgman).
            const float s = h[i] / (h[i] - h[j]);
            out[count++] = v[i] + s * (v[j] - v[i]);
        }
    }
    return count;
}

// Lambert's formula for a polygon seen from a differential area at p with unit normal n (Hottel
// and Sarofim; Sillion and Puech 1994, eq. 2.12): FF = 1 / (2 pi) |sum_i beta_i (n . g_i)|, beta_i
// the angle edge i subtends at p and g_i the unit normal of the plane through p and edge i.
// Valid for a polygon wholly above the tangent plane.
RC_FUNC float rc_decomp_polygon_form_factor(float3 p, float3 n, const float3* vertices, int count) {
    float sum = 0.0f;
    for (int i = 0; i < count; ++i) {
        const float3 a = vertices[i] - p;
        const float3 b = vertices[(i + 1) % count] - p;
        const float3 normal = cross(a, b);
        const float sine = length(normal);
        if (sine <= 0.0f) {
            continue;  // a degenerate edge, or one through p: it subtends nothing
        }
        const float beta = atan2(sine, dot(a, b));
        sum += beta * dot(normal, n) / sine;
    }
    return fabs(sum) * RC_INV_TWO_PI;
}

// FF of the triangle (v0, v1, v2) to the differential area at p with unit normal n: the part
// above the tangent plane, every point of it taken as visible from p.
RC_FUNC float rc_decomp_form_factor(float3 p, float3 n, float3 v0, float3 v1, float3 v2) {
    float3 clipped[RC_DECOMP_CLIPPED_VERTICES];
    const int count = rc_decomp_clip_to_horizon(p, n, v0, v1, v2, clipped);
    return count < 3 ? 0.0f : rc_decomp_polygon_form_factor(p, n, clipped, count);
}
