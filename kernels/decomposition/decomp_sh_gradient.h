// The far field's fit with translational gradients (--decomp-gradients on): a cluster's rays
// start at different points, so the least-squares fit can be first order in space at no extra
// ray, L_D*(x, w) ~= sum_k (c_k + g_k . (x - x_c)) Y_k(w), x_c the cluster's centre; 9
// coefficients and 9 three-vector gradients per colour channel (as irradiance caching's
// translational gradients, Ward and Heckbert 1992, and radiance caching's SH gradients,
// Krivanek et al. 2005, in the course; here fitted, not estimated from the hemisphere's cells).
#pragma once

#include "decomposition/decomp_sh.h"

#define RC_DECOMP_GRADIENT_UNKNOWNS (4 * RC_DECOMP_SH_COEFFICIENTS)
#define RC_DECOMP_GRADIENT_PACKED \
    (RC_DECOMP_GRADIENT_UNKNOWNS * (RC_DECOMP_GRADIENT_UNKNOWNS + 1) / 2)
// Below this many kept rays per unknown of the first-order fit the gradient part is dropped (the
// 9-coefficient fit of the same rays).
#define RC_DECOMP_GRADIENT_MIN_RAYS_PER_UNKNOWN 4

// The normal equations of the first-order fit. The unknowns in blocks of 9: the coefficients,
// then their derivatives along x, y and z in units of `scale` (the kept origins' RMS distance
// from the centre), so every block is of the same magnitude; the Gram matrix as a packed lower
// triangle and the right-hand side, over the kept rays in ray order.
typedef struct ShGradientEquations {
    float gram[RC_DECOMP_GRADIENT_PACKED];
    float3 rhs[RC_DECOMP_GRADIENT_UNKNOWNS];
    float scale;
    uint kept;
} ShGradientEquations;

// The design row of a ray in direction d from normalised offset u: y(d), then y(d) u.x, y(d) u.y,
// y(d) u.z.
RC_FUNC void rc_decomp_gradient_row(float3 d, float3 u, float z[RC_DECOMP_GRADIENT_UNKNOWNS]) {
    float y[RC_DECOMP_SH_COEFFICIENTS];
    rc_decomp_sh_basis(d, y);
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        z[i] = y[i];
        z[RC_DECOMP_SH_COEFFICIENTS + i] = y[i] * u.x;
        z[2 * RC_DECOMP_SH_COEFFICIENTS + i] = y[i] * u.y;
        z[3 * RC_DECOMP_SH_COEFFICIENTS + i] = y[i] * u.z;
    }
}

// The equations of a cluster's kept rays (two passes in ray order: the scale, then the sums).
RC_FUNC void rc_decomp_gradient_equations(const DecompParams* params,
                                          RC_GLOBAL const ClusterRay* rays,
                                          ShGradientEquations* e) {
    float spread = 0.0f;
    e->kept = 0;
    for (int r = 0; r < params->cluster_rays; ++r) {
        if (rays[r].kept != 0) {
            spread += dot(rays[r].offset.xyz, rays[r].offset.xyz);
            e->kept += 1;
        }
    }
    e->scale = e->kept > 0 ? sqrt(spread / (float)e->kept) : 0.0f;
    const float inverse_scale = e->scale > 0.0f ? 1.0f / e->scale : 0.0f;
    for (int i = 0; i < RC_DECOMP_GRADIENT_PACKED; ++i) {
        e->gram[i] = 0.0f;
    }
    for (int i = 0; i < RC_DECOMP_GRADIENT_UNKNOWNS; ++i) {
        e->rhs[i] = (float3)(0.0f);
    }
    for (int r = 0; r < params->cluster_rays; ++r) {
        if (rays[r].kept == 0) {
            continue;
        }
        float z[RC_DECOMP_GRADIENT_UNKNOWNS];
        rc_decomp_gradient_row(rays[r].direction.xyz, rays[r].offset.xyz * inverse_scale, z);
        for (int i = 0; i < RC_DECOMP_GRADIENT_UNKNOWNS; ++i) {
            for (int j = 0; j <= i; ++j) {
                e->gram[rc_decomp_packed(i, j)] += z[i] * z[j];
            }
            e->rhs[i] += z[i] * rays[r].radiance.xyz;
        }
    }
}

// Factors G + Lambda = L L^T in place (e->gram) for the leading n unknowns by Cholesky (the
// leading block's factor is the whole matrix's leading block), Lambda diagonal: lambda_constant
// on the coefficients, lambda_gradient on the gradient part.
RC_FUNC void rc_decomp_gradient_factor(ShGradientEquations* e, int n, float lambda_constant,
                                       float lambda_gradient) {
    float* l = e->gram;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j <= i; ++j) {
            float s = l[rc_decomp_packed(i, j)];
            if (i == j) {
                s += i < RC_DECOMP_SH_COEFFICIENTS ? lambda_constant : lambda_gradient;
            }
            for (int k = 0; k < j; ++k) {
                s -= l[rc_decomp_packed(i, k)] * l[rc_decomp_packed(j, k)];
            }
            l[rc_decomp_packed(i, j)] =
                i == j ? sqrt(fmax(s, 1e-30f)) : s / l[rc_decomp_packed(j, j)];
        }
    }
}

// The solution x of the leading n unknowns' system from the factor and z = L^-1 b.
RC_FUNC void rc_decomp_gradient_back(const ShGradientEquations* e, int n,
                                     const float3 z[RC_DECOMP_GRADIENT_UNKNOWNS],
                                     float3 x[RC_DECOMP_GRADIENT_UNKNOWNS]) {
    for (int i = n - 1; i >= 0; --i) {
        float3 s = z[i];
        for (int k = i + 1; k < n; ++k) {
            s -= e->gram[rc_decomp_packed(k, i)] * x[k];
        }
        x[i] = s / e->gram[rc_decomp_packed(i, i)];
    }
}

// Solves the factored system for the leading n unknowns: the 9-coefficient fit into plain
// (always) and the first-order fit into x (n = RC_DECOMP_GRADIENT_UNKNOWNS; else x = plain).
RC_FUNC void rc_decomp_gradient_solve(const ShGradientEquations* e, int n,
                                      float3 plain[RC_DECOMP_GRADIENT_UNKNOWNS],
                                      float3 x[RC_DECOMP_GRADIENT_UNKNOWNS]) {
    float3 z[RC_DECOMP_GRADIENT_UNKNOWNS];
    for (int i = 0; i < n; ++i) {  // L z = b
        float3 s = e->rhs[i];
        for (int k = 0; k < i; ++k) {
            s -= e->gram[rc_decomp_packed(i, k)] * z[k];
        }
        z[i] = s / e->gram[rc_decomp_packed(i, i)];
    }
    rc_decomp_gradient_back(e, RC_DECOMP_SH_COEFFICIENTS, z, plain);
    rc_decomp_gradient_back(e, n, z, x);
}

// The positive-part James-Stein factor of the gradient block (James and Stein 1961; the block's
// p = 27 unknowns per channel): F = ((RSS_0 - RSS_1) / p) / (RSS_1 / (kept - 36)), RSS_0 and
// RSS_1 the residual sums of squares of the 9-coefficient and first-order fits over the kept
// rays (a third pass in ray order), and the gradient is scaled by max(0, 1 - (p - 2) / (p F)):
// kept nearly whole where the rays' radiance varies with their origins far beyond the fit's
// residual, dropped where that variation is within it (noise, or what order 2 cannot hold).
RC_FUNC float3 rc_decomp_gradient_shrink(const DecompParams* params,
                                         RC_GLOBAL const ClusterRay* rays, float inverse_scale,
                                         const float3 plain[RC_DECOMP_GRADIENT_UNKNOWNS],
                                         const float3 x[RC_DECOMP_GRADIENT_UNKNOWNS], uint kept) {
    float3 rss0 = (float3)(0.0f);
    float3 rss1 = (float3)(0.0f);
    for (int r = 0; r < params->cluster_rays; ++r) {
        if (rays[r].kept == 0) {
            continue;
        }
        float z[RC_DECOMP_GRADIENT_UNKNOWNS];
        rc_decomp_gradient_row(rays[r].direction.xyz, rays[r].offset.xyz * inverse_scale, z);
        float3 fit0 = (float3)(0.0f);
        float3 fit1 = (float3)(0.0f);
        for (int i = 0; i < RC_DECOMP_GRADIENT_UNKNOWNS; ++i) {
            fit0 += i < RC_DECOMP_SH_COEFFICIENTS ? z[i] * plain[i] : (float3)(0.0f);
            fit1 += z[i] * x[i];
        }
        const float3 d0 = rays[r].radiance.xyz - fit0;
        const float3 d1 = rays[r].radiance.xyz - fit1;
        rss0 += d0 * d0;
        rss1 += d1 * d1;
    }
    const float p = (float)(RC_DECOMP_GRADIENT_UNKNOWNS - RC_DECOMP_SH_COEFFICIENTS);
    const float3 variance = rss1 / (float)(kept - RC_DECOMP_GRADIENT_UNKNOWNS);
    const float3 explained = fmax(rss0 - rss1, (float3)(0.0f)) / p;
    // explained / F = variance: the factor 1 - (p - 2) variance / (p explained), in [0, 1].
    const float3 factor = (float3)(1.0f) - (p - 2.0f) * variance / (p * explained);
    return select(clamp(factor, 0.0f, 1.0f), (float3)(0.0f), explained <= (float3)(0.0f));
}

// A cluster's first-order fit (rc_decomp_fit_cluster's with gradients): the coefficients at the
// centre and their gradients per scene unit. The regularisation (docs/decomposition.md):
// 1. A Tikhonov term. The coefficients keep rc_decomp_solve's, ridge * kept / (4 pi); the
//    gradient part gets gradient_ridge * kept / (4 pi) with the offsets in units of their RMS
//    distance from the centre. Under uniform sampling the Gram diagonal of the derivative along
//    an axis is kept / (4 pi) times the offsets' mean square along it (v; their total is 1), so
//    the term shrinks that derivative by v / (v + gradient_ridge): a direction the cluster's
//    points do not span (the normal of a flat cluster: v = 0) gets no gradient.
// 2. Significance: the gradient block is shrunk towards 0 by the positive-part James-Stein
//    factor of its F statistic (rc_decomp_gradient_shrink), the coefficients moved by the same
//    factor from the 9-coefficient fit's towards the first-order fit's.
// 3. Below RC_DECOMP_GRADIENT_MIN_RAYS_PER_UNKNOWN kept rays per unknown, or when every kept ray
//    starts at the centre, the gradient is dropped: all zero, the 9-coefficient fit.
RC_FUNC void rc_decomp_fit_with_gradients(const DecompParams* params,
                                          RC_GLOBAL const ClusterRay* rays, ClusterFit* fit) {
    ShGradientEquations e;
    rc_decomp_gradient_equations(params, rays, &e);
    float3 x[RC_DECOMP_GRADIENT_UNKNOWNS];
    for (int i = 0; i < RC_DECOMP_GRADIENT_UNKNOWNS; ++i) {
        x[i] = (float3)(0.0f);
    }
    const bool with_gradient =
        e.scale > 0.0f &&
        e.kept >= (uint)(RC_DECOMP_GRADIENT_MIN_RAYS_PER_UNKNOWN * RC_DECOMP_GRADIENT_UNKNOWNS);
    if (e.kept > 0) {
        const float per_ray = (float)e.kept * RC_INV_FOUR_PI;
        const int n = with_gradient ? RC_DECOMP_GRADIENT_UNKNOWNS : RC_DECOMP_SH_COEFFICIENTS;
        float3 plain[RC_DECOMP_GRADIENT_UNKNOWNS];
        rc_decomp_gradient_factor(&e, n, params->ridge * per_ray, params->gradient_ridge * per_ray);
        rc_decomp_gradient_solve(&e, n, plain, x);
        if (with_gradient) {
            const float3 shrink =
                rc_decomp_gradient_shrink(params, rays, 1.0f / e.scale, plain, x, e.kept);
            for (int i = 0; i < RC_DECOMP_GRADIENT_UNKNOWNS; ++i) {  // the coefficients: from
                // the 9-coefficient fit's towards the first-order fit's by the same factor
                x[i] = i < RC_DECOMP_SH_COEFFICIENTS ? plain[i] + shrink * (x[i] - plain[i])
                                                     : shrink * x[i];
            }
        }
    }
    const float inverse_scale = e.scale > 0.0f ? 1.0f / e.scale : 0.0f;
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        fit->sample.coefficients[i] = (float4)(x[i], 0.0f);
        fit->gradient.along_x[i] = (float4)(x[RC_DECOMP_SH_COEFFICIENTS + i] * inverse_scale, 0.0f);
        fit->gradient.along_y[i] =
            (float4)(x[2 * RC_DECOMP_SH_COEFFICIENTS + i] * inverse_scale, 0.0f);
        fit->gradient.along_z[i] =
            (float4)(x[3 * RC_DECOMP_SH_COEFFICIENTS + i] * inverse_scale, 0.0f);
    }
    fit->kept = e.kept;
}
