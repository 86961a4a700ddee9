// BRDF tables of radiance caching (DESIGN.md §6.4; TVCG 2005 §4.1 after Kautz, Sloan and Snyder
// 2002): for outgoing directions w_o on a parabolic-map grid (rc_parabolic.h), the coefficient
// vector of the cosine-weighted specular lobe F(w_i) = f_s(w_o, w_i) cos(theta_i) (TVCG eq. 2, 3:
// c_l^m(w_o) = integral over the hemisphere of F Y_l^m), so that the glossy reflection of
// incoming radiance with coefficients lambda is the dot product sum lambda_l^m c_l^m(w_o)
// (TVCG eq. 13). The lobe is the material's specular term with unit specular reflectance
// (kernels/common/material.h): callers scale by Material.specular; the Lambertian lobe is
// irradiance caching's.
#pragma once

#include "common/material.h"
#include "radiance_cache/rc_parabolic.h"
#include "shared/radiance_cache.h"
#include "shared/spherical_harmonics.h"

// F(w_i) for unit specular reflectance (rc_specular_lobe).
RC_FUNC float rc_brdf_table_lobe(const Material* material, float3 wo, float3 wi) {
    return rc_specular_lobe(material, wo, wi);
}

// The coefficients c[0 .. RC_SH_MAX_COEFFICIENTS) of texel `texel` and its representation error
// at every order, errors[n - 1] for n = 1 .. RC_SH_MAX_ORDER. The integral is a product rule:
// Gauss-Legendre in z = cos(theta_i) over [0, 1] (nodes[2 j], weight nodes[2 j + 1]) times the
// midpoint rule in phi_i. Separated (the fast SH transform): per z node, the Fourier sums
// A_m = sum_k F cos(m phi_k), B_m = sum_k F sin(m phi_k), then
//   c_l^m = sum_j w_j (2 pi / N_phi) Y_l^|m|(theta_j, 0) (A_m for m >= 0, B_|m| for m < 0),
// Y_l^|m|(theta, 0) being the polar factor (with sqrt 2 for m > 0). For SH the rule is half of a
// composite rule over the sphere on which F vanishes below the horizon, for HSH a rule over the
// hemisphere; with theta_nodes >= RC_SH_MAX_ORDER and phi_nodes >= 2 RC_SH_MAX_ORDER both
// integrate products of two basis functions exactly, so Bessel's inequality holds for the
// discrete norm and the error of order n, measured as Ramamoorthi and Hanrahan do (TVCG §4.1
// after [33]; HSH paper eq. 15: the energy the first n^2 coefficients miss), is
//   e_n = sqrt(1 - sum_{i < n^2} c_i^2 / |F|^2)   (0 for a zero lobe).
RC_FUNC void rc_brdf_table_texel(const Material* material, const BrdfTableParams* params, int texel,
                                 RC_GLOBAL const float* nodes, float* c, float* errors) {
    const int resolution = params->resolution;
    const float3 wo = rc_parabolic_to_direction(
        rc_parabolic_texel_centre(texel % resolution, texel / resolution, resolution));
    for (int i = 0; i < RC_SH_MAX_COEFFICIENTS; ++i) {
        c[i] = 0.0f;
    }
    const float d_phi = 2.0f * RC_PI / (float)params->phi_nodes;
    const float step_cos = cos(d_phi);
    const float step_sin = sin(d_phi);
    float norm2 = 0.0f;
    float polar[RC_SH_MAX_COEFFICIENTS];
    for (int j = 0; j < params->theta_nodes; ++j) {
        const float z = nodes[2 * j];
        const float weight = nodes[2 * j + 1] * d_phi;
        const float s = sqrt(fmax(0.0f, 1.0f - z * z));
        float a[RC_SH_MAX_ORDER];
        float b[RC_SH_MAX_ORDER];
        for (int m = 0; m < RC_SH_MAX_ORDER; ++m) {
            a[m] = 0.0f;
            b[m] = 0.0f;
        }
        float row_norm2 = 0.0f;
        // phi_k = (k + 1/2) d_phi by repeated rotation through d_phi.
        float cos_phi = cos(0.5f * d_phi);
        float sin_phi = sin(0.5f * d_phi);
        for (int k = 0; k < params->phi_nodes; ++k) {
            const float f = rc_brdf_table_lobe(material, wo, (float3)(s * cos_phi, s * sin_phi, z));
            row_norm2 += f * f;
            float cos_m = 1.0f;
            float sin_m = 0.0f;
            for (int m = 0; m < RC_SH_MAX_ORDER; ++m) {
                a[m] += f * cos_m;
                b[m] += f * sin_m;
                const float next = cos_m * cos_phi - sin_m * sin_phi;
                sin_m = sin_m * cos_phi + cos_m * sin_phi;
                cos_m = next;
            }
            const float next_cos = cos_phi * step_cos - sin_phi * step_sin;
            sin_phi = sin_phi * step_cos + cos_phi * step_sin;
            cos_phi = next_cos;
        }
        norm2 += weight * row_norm2;
        rc_basis_eval(params->basis, s, 0.0f, z, RC_SH_MAX_ORDER, polar);
        for (int l = 0; l < RC_SH_MAX_ORDER; ++l) {
            c[rc_sh_index(l, 0)] += weight * polar[rc_sh_index(l, 0)] * a[0];
            for (int m = 1; m <= l; ++m) {
                const float p = weight * polar[rc_sh_index(l, m)];
                c[rc_sh_index(l, m)] += p * a[m];
                c[rc_sh_index(l, -m)] += p * b[m];
            }
        }
    }
    float captured = 0.0f;
    for (int n = 1; n <= RC_SH_MAX_ORDER; ++n) {
        for (int i = (n - 1) * (n - 1); i < n * n; ++i) {
            captured += c[i] * c[i];
        }
        errors[n - 1] = norm2 > 0.0f ? sqrt(fmax(0.0f, 1.0f - captured / norm2)) : 0.0f;
    }
}

// Bilinear position of w_o in a table: the texel (i0, j0) below-left of it, both in
// [0, resolution - 2], and the weights (fu, fv) of the texels to the right and above.
RC_FUNC void rc_brdf_table_position(const BrdfTableInfo* info, float3 wo, int* i0, int* j0,
                                    float* fu, float* fv) {
    const int g = info->resolution;
    const float2 p = rc_parabolic_from_direction(wo);
    const float u = (p.x + 1.0f) * 0.5f * (float)g - 0.5f;
    const float v = (p.y + 1.0f) * 0.5f * (float)g - 0.5f;
    *i0 = clamp((int)floor(u), 0, g - 2);
    *j0 = clamp((int)floor(v), 0, g - 2);
    *fu = clamp(u - (float)*i0, 0.0f, 1.0f);
    *fv = clamp(v - (float)*j0, 0.0f, 1.0f);
}

// The first order^2 coefficients of the lobe for w_o (w_o.z > 0), bilinear between the four
// nearest texel centres.
RC_FUNC void rc_brdf_table_coefficients(RC_GLOBAL const float* coefficients,
                                        const BrdfTableInfo* info, float3 wo, int order,
                                        float* out) {
    int i0, j0;
    float fu, fv;
    rc_brdf_table_position(info, wo, &i0, &j0, &fu, &fv);
    const int t00 = info->first_texel + j0 * info->resolution + i0;
    const int t10 = t00 + 1;
    const int t01 = t00 + info->resolution;
    const int t11 = t01 + 1;
    const float w00 = (1.0f - fu) * (1.0f - fv);
    const float w10 = fu * (1.0f - fv);
    const float w01 = (1.0f - fu) * fv;
    const float w11 = fu * fv;
    const int count = rc_sh_count(order);
    for (int i = 0; i < count; ++i) {
        out[i] = w00 * coefficients[t00 * RC_SH_MAX_COEFFICIENTS + i] +
                 w10 * coefficients[t10 * RC_SH_MAX_COEFFICIENTS + i] +
                 w01 * coefficients[t01 * RC_SH_MAX_COEFFICIENTS + i] +
                 w11 * coefficients[t11 * RC_SH_MAX_COEFFICIENTS + i];
    }
}

// The order to use for w_o: the highest of the four texels the lookup blends, or 0 (Monte Carlo)
// when any of them is beyond n_max.
RC_FUNC int rc_brdf_table_order(RC_GLOBAL const int* orders, const BrdfTableInfo* info, float3 wo) {
    int i0, j0;
    float fu, fv;
    rc_brdf_table_position(info, wo, &i0, &j0, &fu, &fv);
    const int t00 = info->first_texel + j0 * info->resolution + i0;
    const int o[4] = {orders[t00], orders[t00 + 1], orders[t00 + info->resolution],
                      orders[t00 + info->resolution + 1]};
    int order = 0;
    for (int i = 0; i < 4; ++i) {
        if (o[i] == 0) {
            return 0;
        }
        order = max(order, o[i]);
    }
    return order;
}
