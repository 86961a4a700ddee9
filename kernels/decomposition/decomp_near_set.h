// Which split triangles belong to a shading point's near set T (eq. 4 of the paper): the paper's
// rule, the triangles whose centroid lies within alpha (§5), or, with --decomp-near touching
// (the default), those with any point within alpha. The far field's rays discard every hit
// closer than alpha (§4), so with the centroid rule the parts of a triangle within alpha whose
// centroid lies beyond it are in neither term and send the fit's extrapolated L_D*; a touching
// triangle is counted whole, its FF [B - pi L_D*] replacing the far term over all of it
// (docs/lab/decomposition.md, "The crease bias").
#pragma once

#include "common/math.h"
#include "shared/decomposition.h"

// The squared distance from p to the closest point of triangle (a, b, c): the closest point by
// the Voronoi regions of the triangle's vertices, edges and face (Ericson, "Real-Time Collision
// Detection", 2005, §5.1.5).
RC_FUNC float rc_decomp_point_triangle_distance2(float3 p, float3 a, float3 b, float3 c) {
    const float3 ab = b - a;
    const float3 ac = c - a;
    const float3 ap = p - a;
    const float d1 = dot(ab, ap);
    const float d2 = dot(ac, ap);
    float3 closest;
    if (d1 <= 0.0f && d2 <= 0.0f) {
        closest = a;  // vertex region a
    } else {
        const float3 bp = p - b;
        const float d3 = dot(ab, bp);
        const float d4 = dot(ac, bp);
        const float3 cp = p - c;
        const float d5 = dot(ab, cp);
        const float d6 = dot(ac, cp);
        const float vc = d1 * d4 - d3 * d2;
        const float vb = d5 * d2 - d1 * d6;
        const float va = d3 * d6 - d5 * d4;
        if (d3 >= 0.0f && d4 <= d3) {
            closest = b;  // vertex region b
        } else if (d6 >= 0.0f && d5 <= d6) {
            closest = c;  // vertex region c
        } else if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
            closest = a + (d1 / (d1 - d3)) * ab;  // edge ab
        } else if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
            closest = a + (d2 / (d2 - d6)) * ac;  // edge ac
        } else if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
            closest = b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);  // edge bc
        } else {
            const float denominator = 1.0f / (va + vb + vc);  // the face
            closest = a + (vb * denominator) * ab + (vc * denominator) * ac;
        }
    }
    const float3 offset = p - closest;
    return dot(offset, offset);
}

// Whether triangle (v0, v1, v2) is in p's near set under `rule` (RC_DECOMP_NEAR_CENTROID or
// RC_DECOMP_NEAR_TOUCHING): strictly within alpha, so alpha = 0 has an empty near set.
RC_FUNC bool rc_decomp_in_near_set(int rule, float3 p, float3 v0, float3 v1, float3 v2,
                                   float alpha) {
    float distance2;
    if (rule == RC_DECOMP_NEAR_TOUCHING) {
        distance2 = rc_decomp_point_triangle_distance2(p, v0, v1, v2);
    } else {
        const float3 offset = (v0 + v1 + v2) * (1.0f / 3.0f) - p;
        distance2 = dot(offset, offset);
    }
    return distance2 < alpha * alpha;
}
