// The far field's spherical harmonics (the paper, §4): the least-squares fit of L_D* to a
// cluster's rays, L_D* in one direction, and the distant term I_D as a dot product with the
// clamped cosine's coefficients (Ramamoorthi and Hanrahan 2001).
#pragma once

#include "common/math.h"
#include "shared/decomposition.h"
#include "shared/spherical_harmonics.h"

// The 9 basis functions at a unit direction.
RC_FUNC void rc_decomp_sh_basis(float3 d, float y[RC_DECOMP_SH_COEFFICIENTS]) {
    rc_sh_eval(d.x, d.y, d.z, RC_DECOMP_SH_ORDER, y);
}

// L_D* of a sample in direction d (rgb), never negative: a fit may undershoot where its rays left
// directions unsampled.
RC_FUNC float3 rc_decomp_sh_radiance(const ShSample* sample, float3 d) {
    float y[RC_DECOMP_SH_COEFFICIENTS];
    rc_decomp_sh_basis(d, y);
    float3 sum = (float3)(0.0f);
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        sum += y[i] * sample->coefficients[i].xyz;
    }
    return fmax(sum, (float3)(0.0f));
}

// I_D = integral over the hemisphere about n of cos L_D* (§4: "a dot product of harmonic
// coefficients for max(N . w, 0) and L_D*"): by the Funk-Hecke theorem the clamped cosine's
// band-l coefficients are A_l Y_lm(n), A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4 (Ramamoorthi and
// Hanrahan, "An Efficient Representation for Irradiance Environment Maps", 2001, eq. 8).
RC_FUNC float3 rc_decomp_sh_irradiance(const ShSample* sample, float3 n) {
    float y[RC_DECOMP_SH_COEFFICIENTS];
    rc_decomp_sh_basis(n, y);
    float3 sum = (float3)(0.0f);
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        const float band = i == 0 ? RC_PI : (i < 4 ? 2.0f * RC_PI / 3.0f : 0.25f * RC_PI);
        sum += band * y[i] * sample->coefficients[i].xyz;
    }
    return sum;
}

// Entry (i, j) of the packed lower triangle of a symmetric 9 x 9 matrix, i >= j.
RC_FUNC int rc_decomp_packed(int i, int j) { return i * (i + 1) / 2 + j; }

#define RC_DECOMP_PACKED_SIZE (RC_DECOMP_SH_COEFFICIENTS * (RC_DECOMP_SH_COEFFICIENTS + 1) / 2)

// The normal equations of the least-squares fit (§4: "The spherical harmonic coefficients
// approximating L_D* are computed by a least-squares fit to these incident radiance samples"):
// the Gram matrix G = sum_k y(d_k) y(d_k)^T (packed lower triangle) and b = sum_k y(d_k) L_k over
// the kept rays, in ray order.
typedef struct ShNormalEquations {
    float gram[RC_DECOMP_PACKED_SIZE];
    float3 rhs[RC_DECOMP_SH_COEFFICIENTS];
    uint kept;
} ShNormalEquations;

RC_FUNC void rc_decomp_normal_equations_init(ShNormalEquations* e) {
    for (int i = 0; i < RC_DECOMP_PACKED_SIZE; ++i) {
        e->gram[i] = 0.0f;
    }
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        e->rhs[i] = (float3)(0.0f);
    }
    e->kept = 0;
}

RC_FUNC void rc_decomp_normal_equations_add(ShNormalEquations* e, float3 direction,
                                            float3 radiance) {
    float y[RC_DECOMP_SH_COEFFICIENTS];
    rc_decomp_sh_basis(direction, y);
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        for (int j = 0; j <= i; ++j) {
            e->gram[rc_decomp_packed(i, j)] += y[i] * y[j];
        }
        e->rhs[i] += y[i] * radiance;
    }
    e->kept += 1;
}

// The coefficients solving (G + lambda I) c = b by Cholesky factorisation, lambda = ridge * kept /
// (4 pi): a Tikhonov term scaled like G's diagonal under uniform sampling of the sphere (each
// Y_i^2 averages 1 / (4 pi)), which keeps the fit bounded where the kept rays leave directions
// unsampled (a cluster in a corner, where the near surfaces' rays were discarded). No kept ray:
// all coefficients 0 (L_D* = 0: nothing lies beyond alpha).
RC_FUNC void rc_decomp_solve(const ShNormalEquations* e, float ridge, ShSample* out) {
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        out->coefficients[i] = (float4)(0.0f);
    }
    if (e->kept == 0) {
        return;
    }
    const float lambda = ridge * (float)e->kept * RC_INV_FOUR_PI;
    float l[RC_DECOMP_PACKED_SIZE];  // the Cholesky factor L, G + lambda I = L L^T
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        for (int j = 0; j <= i; ++j) {
            float s = e->gram[rc_decomp_packed(i, j)] + (i == j ? lambda : 0.0f);
            for (int k = 0; k < j; ++k) {
                s -= l[rc_decomp_packed(i, k)] * l[rc_decomp_packed(j, k)];
            }
            l[rc_decomp_packed(i, j)] =
                i == j ? sqrt(fmax(s, 1e-30f)) : s / l[rc_decomp_packed(j, j)];
        }
    }
    float3 z[RC_DECOMP_SH_COEFFICIENTS];  // L z = b, then L^T c = z
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        float3 s = e->rhs[i];
        for (int k = 0; k < i; ++k) {
            s -= l[rc_decomp_packed(i, k)] * z[k];
        }
        z[i] = s / l[rc_decomp_packed(i, i)];
    }
    for (int i = RC_DECOMP_SH_COEFFICIENTS - 1; i >= 0; --i) {
        float3 s = z[i];
        for (int k = i + 1; k < RC_DECOMP_SH_COEFFICIENTS; ++k) {
            s -= l[rc_decomp_packed(k, i)] * out->coefficients[k].xyz;
        }
        out->coefficients[i] = (float4)(s / l[rc_decomp_packed(i, i)], 0.0f);
    }
}
