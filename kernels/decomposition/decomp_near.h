// The near field (the paper, §5): the correction I_N of eq. 4 at a shading point from the split
// triangles whose centroids lie within alpha, their form factors taken as wholly visible after
// the paper's visibility heuristic, and their coarse radiosities.
#pragma once

#include "decomposition/decomp_form_factor.h"
#include "decomposition/decomp_sh.h"
#include "irradiance_cache/ic_records.h"  // rc_ic_grid_cell: the record grid's cell of a point

// The near triangles as the kernels read them: the triangles, the outgoing radiance of each
// one's front, B(t) / pi (the coarse solution, emission left out), and a record grid over their
// centroids with reach alpha (cell c lists the triangles whose centroid lies within alpha of some
// point of it, ascending).
typedef struct NearField {
    RecordGrid grid;
    RC_GLOBAL const int* cell_start;
    RC_GLOBAL const int* cell_triangles;
    RC_GLOBAL const NearTriangle* triangles;
    RC_GLOBAL const float4* radiance;
    float alpha;
} NearField;

// The paper's visibility heuristic (§5): "discards any triangles that are either back-facing to
// the shading point, P, or that are completely below the plane passing through P with normal N
// ... We then assume that all other triangles within distance alpha are visible". `tolerance`
// (a small length) keeps p's own triangle and its coplanar neighbours out.
RC_FUNC bool rc_decomp_may_see(float3 p, float3 n, float3 v0, float3 v1, float3 v2,
                               float tolerance) {
    const float3 normal = cross(v1 - v0, v2 - v0);
    const float length_normal = length(normal);
    if (length_normal <= 0.0f || dot(normal, p - v0) <= tolerance * length_normal) {
        return false;  // back-facing (or edge-on)
    }
    return dot(v0 - p, n) > tolerance || dot(v1 - p, n) > tolerance || dot(v2 - p, n) > tolerance;
}

// I_N at point p with unit normal n (eq. 4): the sum over the triangles t whose centroid lies
// within alpha and that pass the heuristic of FF(t) [B(t) - pi L_D*(P, w_t)], w_t the direction
// to t's centroid and L_D* read from the interpolated far field `far` (the two terms of the
// bracket are the power the triangle reflects towards p and the distant power it hides). The
// triangles are visited in the grid cell's order. *count receives the triangles summed.
RC_FUNC float3 rc_decomp_near_correction(const NearField* near, const ShSample* far, float3 p,
                                         float3 n, uint* count) {
    float3 sum = (float3)(0.0f);
    *count = 0;
    const int cell = rc_ic_grid_cell(&near->grid, p);
    if (cell < 0) {
        return sum;
    }
    const float tolerance = 1e-4f * near->alpha;
    for (int k = near->cell_start[cell]; k < near->cell_start[cell + 1]; ++k) {
        const int t = near->cell_triangles[k];
        const float3 v0 = near->triangles[t].v0.xyz;
        const float3 v1 = near->triangles[t].v1.xyz;
        const float3 v2 = near->triangles[t].v2.xyz;
        const float3 centroid = (v0 + v1 + v2) * (1.0f / 3.0f);
        const float3 offset = centroid - p;
        if (dot(offset, offset) >= near->alpha * near->alpha ||
            !rc_decomp_may_see(p, n, v0, v1, v2, tolerance)) {
            continue;
        }
        const float ff = rc_decomp_form_factor(p, n, v0, v1, v2);
        if (ff <= 0.0f) {
            continue;
        }
        const float3 hidden = rc_decomp_sh_radiance(far, normalize(offset));
        sum += ff * RC_PI * (near->radiance[t].xyz - hidden);
        *count += 1;
    }
    return sum;
}
