// Projection of a record's incoming radiance onto the (hemi)spherical harmonics (DESIGN.md §6.4):
// the Monte Carlo quadrature of the course's "Incoming Radiance Computation" slide (TVCG 2005
// §4.2 eq. 4, HSH paper eq. 22),
//   lambda_l^m = 2 pi / (M N) sum_{j, k} L_{j,k} Y_l^m(theta_j, phi_k),
// per colour channel, over the uniform strata of radiance_hemisphere.h.
#pragma once

#include "caching/radiance_hemisphere.h"
#include "shared/spherical_harmonics.h"

// Adds weighted.c * Y_i(d) to coefficients[c * order^2 + i] for the channels c = r, g, b.
RC_FUNC void rc_basis_accumulate(int basis, float3 d, float3 weighted, int order,
                                 float* coefficients) {
    float y[RC_SH_MAX_COEFFICIENTS];
    rc_basis_eval(basis, d.x, d.y, d.z, order, y);
    const int count = rc_sh_count(order);
    for (int i = 0; i < count; ++i) {
        coefficients[i] += weighted.x * y[i];
        coefficients[count + i] += weighted.y * y[i];
        coefficients[2 * count + i] += weighted.z * y[i];
    }
}

// The coefficient vectors (r, g, b: 3 order^2 floats) of one record from its m x n cells:
// cells[c].xyz is the radiance that arrived from the direction of cell c = j n + k, drawn by
// rc_stratum_direction(key_lo, key_hi, record, c, m, n). Sums in cell order (deterministic).
RC_FUNC void rc_project_cells(RC_GLOBAL const float4* cells, int m, int n, uint key_lo, uint key_hi,
                              uint record, int basis, int order, float* coefficients) {
    const int count = rc_sh_count(order);
    for (int i = 0; i < 3 * count; ++i) {
        coefficients[i] = 0.0f;
    }
    const float weight = rc_uniform_stratum_weight(m, n);
    for (int c = 0; c < m * n; ++c) {
        const float3 d = rc_stratum_direction(key_lo, key_hi, record, c, m, n);
        rc_basis_accumulate(basis, d, weight * cells[c].xyz, order, coefficients);
    }
}
