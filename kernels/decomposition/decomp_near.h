// The near field (the paper, §5): the correction I_N of eq. 4 at a shading point from the split
// triangles of its near set (decomp_near_set.h: any point, or the centroid, within alpha), their
// form factors taken as wholly visible after the paper's visibility heuristic (or, with
// --decomp-visibility rays, after a shadow ray to each one's centroid), and their coarse
// radiosities.
#pragma once

#include "caching/irradiance_records.h"  // rc_ic_grid_cell: the record grid's cell of a point
#include "common/path_radiance.h"
#include "decomposition/decomp_form_factor.h"
#include "decomposition/decomp_near_set.h"
#include "decomposition/decomp_sh.h"

// The near triangles as the kernels read them: the triangles, the outgoing radiance of each
// one's front, B(t) / pi (the coarse solution, emission left out), the near set's rule, and a
// record grid over their centroids (cell c lists, ascending, every triangle that may be in the
// near set of some point of it: reach alpha about the centroid with the centroid rule, alpha plus
// the farthest vertex's distance from it with the touching rule). With a scene, a triangle that
// passes the heuristic counts only when a shadow ray reaches its centroid (--decomp-visibility
// rays).
typedef struct NearField {
    RecordGrid grid;
    RC_GLOBAL const int* cell_start;
    RC_GLOBAL const int* cell_triangles;
    RC_GLOBAL const NearTriangle* triangles;
    RC_GLOBAL const float4* radiance;
    float alpha;
    int rule;                     // RC_DECOMP_NEAR_CENTROID or RC_DECOMP_NEAR_TOUCHING
    const SceneData* visibility;  // 0: the paper's heuristic alone
} NearField;

// The near field of a kernel's arguments: B(t) / pi in `radiance`, alpha, the near set's rule and
// the visibility test from params (a shadow ray through `scene` with --decomp-visibility rays).
RC_FUNC NearField rc_decomp_near_field(RecordGrid grid, RC_GLOBAL const int* cell_start,
                                       RC_GLOBAL const int* cell_triangles,
                                       RC_GLOBAL const NearTriangle* triangles,
                                       RC_GLOBAL const float4* radiance, const DecompParams* params,
                                       const SceneData* scene) {
    const NearField near = {
        grid,     cell_start,    cell_triangles,   triangles,
        radiance, params->alpha, params->near_set, params->near_visibility != 0 ? scene : 0};
    return near;
}

// Whether a shadow ray from `origin` (the shading point's ray origin) reaches just short of the
// centroid of a near triangle; counted in *rays.
RC_FUNC bool rc_decomp_reaches(const SceneData* scene, float3 origin, float3 centroid, uint* rays) {
    *rays += 1;
    const float3 target = centroid + 1e-3f * (origin - centroid);
    return !rc_occluded(scene, origin, target, false, target - origin);
}

// The paper's visibility heuristic (§5): "discards any triangles that are either back-facing to
// the shading point, P, or that are completely below the plane passing through P with normal N
// ... We then assume that all other triangles within distance alpha are visible". `tolerance`
// (a small length) keeps p's own triangle and its coplanar neighbours out.
RC_FUNC bool rc_decomp_may_see(float3 p, float3 n, float3 v0, float3 v1, float3 v2,
                               float tolerance) {
    const float3 normal = cross(v1 - v0, v2 - v0);
    const float facing = dot(normal, p - v0);
    if (facing <= 0.0f) {
        return false;  // back-facing or edge-on, decided without the normal's length
    }
    const float length_normal = length(normal);
    if (length_normal <= 0.0f || facing <= tolerance * length_normal) {
        return false;  // back-facing (or edge-on)
    }
    return dot(v0 - p, n) > tolerance || dot(v1 - p, n) > tolerance || dot(v2 - p, n) > tolerance;
}

// The largest subdivision of a near triangle's quadrature: m^2 pieces.
#define RC_DECOMP_MAX_PIECES_PER_EDGE 4

// The distant power a near triangle of form factor ff hides from p (the second term of eq. 4's
// bracket over pi): the paper takes L_D* as "constant over directions spanned by one of the split
// triangles", L_D*(w_t) FF(t). A triangle close to p spans a wide cone over which the order-2 fit
// varies, so here L_D* is averaged over m^2 pieces on a regular grid of the triangle's
// barycentric coordinates, m = the triangle's longest edge over half its centroid's distance (1 to
// RC_DECOMP_MAX_PIECES_PER_EDGE), each piece weighted by its share of ff: the point-to-disc
// estimate cos(theta_p) cos(theta_t) A_k / (pi r^2 + A_k) at its centroid (the pieces' areas A_k
// are equal and cos(theta_t) r is p's height over the triangle's plane, the same for all). The
// exact ff keeps the sum right for constant L_D*; the weights cost no form factor per piece
// (tested against a quadrature; measured on the relief: docs/lab/decomposition.md, "Time").
// Returns FF(t) times that mean of L_D*.
RC_FUNC float3 rc_decomp_hidden(const ShSample* far, float3 p, float3 n, float3 v0, float3 v1,
                                float3 v2, float ff) {
    const float3 e1 = v1 - v0;
    const float3 e2 = v2 - v0;
    const float3 to_centroid = (v0 + v1 + v2) * (1.0f / 3.0f) - p;
    const float longest = fmax(length(e1), fmax(length(e2), length(v2 - v1)));
    const int m = (int)clamp(ceil(2.0f * longest / fmax(length(to_centroid), 1e-30f)), 1.0f,
                             (float)RC_DECOMP_MAX_PIECES_PER_EDGE);
    if (m == 1) {
        return ff * rc_decomp_sh_radiance(far, normalize(to_centroid));
    }
    const float step = 1.0f / (float)m;
    const float piece_area = 0.5f * length(cross(e1, e2)) * step * step;
    float3 sum = (float3)(0.0f);
    float weights = 0.0f;
    for (int i = 0; i < m; ++i) {
        for (int j = 0; i + j < m; ++j) {
            // The upward piece at lattice point (i, j), and the downward one beside it: their
            // centroids at barycentric (i + 1/3, j + 1/3) and (i + 2/3, j + 2/3) steps.
            for (int down = 0; down < 2 && (down == 0 || i + j + 1 < m); ++down) {
                const float shift = down == 0 ? 1.0f / 3.0f : 2.0f / 3.0f;
                const float3 d =
                    v0 + (((float)i + shift) * e1 + ((float)j + shift) * e2) * step - p;
                const float r2 = dot(d, d);
                const float cosine = dot(n, d);
                if (cosine <= 0.0f || r2 <= 0.0f) {
                    continue;
                }
                const float weight = cosine / (r2 * (RC_PI * r2 + piece_area));
                sum += weight * rc_decomp_sh_radiance(far, d / sqrt(r2));
                weights += weight;
            }
        }
    }
    return weights > 0.0f ? (ff / weights) * sum
                          : ff * rc_decomp_sh_radiance(far, normalize(to_centroid));
}

// I_N at point p with unit normal n (eq. 4): the sum over the triangles t of p's near set
// (rc_decomp_in_near_set) that pass the heuristic of FF(t) [B(t) - pi L_D*(P, w_t)], w_t the
// direction to t's centroid and L_D* read from the interpolated far field `far` (the two terms of
// the bracket are the power the triangle reflects towards p and the distant power it hides; the
// latter by rc_decomp_hidden's quadrature). The
// triangles are visited in the grid cell's order. *count receives the triangles summed, *rays the
// shadow rays traced (with near->visibility; from `origin`, p's ray origin).
RC_FUNC float3 rc_decomp_near_correction(const NearField* near, const ShSample* far, float3 p,
                                         float3 origin, float3 n, uint* count, uint* rays) {
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
        if (!rc_decomp_may_see(p, n, v0, v1, v2, tolerance) ||
            !rc_decomp_in_near_set(near->rule, p, v0, v1, v2, near->alpha)) {
            continue;
        }
        const float ff = rc_decomp_form_factor(p, n, v0, v1, v2);
        if (ff <= 0.0f || (near->visibility != 0 &&
                           !rc_decomp_reaches(near->visibility, origin, centroid, rays))) {
            continue;
        }
        sum += RC_PI * (ff * near->radiance[t].xyz - rc_decomp_hidden(far, p, n, v0, v1, v2, ff));
        *count += 1;
    }
    return sum;
}
