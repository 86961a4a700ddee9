// Translational gradients of a radiance record's coefficients (DESIGN.md §6.4; Křivánek,
// Gautron, Bouatouch, Pattanaik, "Improved Radiance Gradient Computation", SCCG 2005, reprinted
// in the course, §3 eq. 2-6; the course's "Gradient Computation" slide): Ward and Heckbert's
// wall-movement argument for the uniform strata of radiance_hemisphere.h, with each cell's marginal
// radiance change weighted by the basis function at the cell's direction:
//   grad lambda_l^m = sum_k [ u_k 2pi/N sum_{j>=1} cos(theta_j-) sin(theta_j-) /
//                                   min(r_jk, r_j-1,k) (L_jk - L_j-1,k) H(theta_jk, phi_jk)
//                           + v_k- sum_j (theta_j+ - theta_j-) / min(r_jk, r_j,k-1)
//                                   (L_jk - L_j,k-1) H(theta_jk, phi_jk) ],
// cos(theta_j-) = 1 - j/M (the wall between cells (j-1, k) and (j, k)), u_k the horizontal unit
// vector at the cell's central azimuth phi_k = 2 pi (k + 1/2)/N, v_k- the horizontal unit
// vector at azimuth 2 pi k / N + pi/2 (the normal of the wall between cells (j, k-1) and (j, k);
// k - 1 wraps around). The paper's azimuthal factor 1 / (M sin(theta_jk)) is replaced by the
// row's polar width theta_j+ - theta_j- (the wall's sweep integrated along its length, below).
// The directions are rc_grid_stratum_direction's jittered grid. Only the x and y derivatives, in
// the record's frame (the paper's §3: z displacements are small and are disregarded).
#pragma once

#include "radiance_cache/rc_projection.h"

// Adds weights.c * Y_i(d) * (gx, gy) to the gradient vectors of channel c: gradients[(2 c) *
// order^2 + i] (x) and gradients[(2 c + 1) * order^2 + i] (y).
RC_FUNC void rc_gradient_accumulate(const float* y, int count, float3 weights, float gx, float gy,
                                    float* gradients) {
    const float w[3] = {weights.x, weights.y, weights.z};
    for (int c = 0; c < 3; ++c) {
        float* x_vector = gradients + 2 * c * count;
        float* y_vector = x_vector + count;
        for (int i = 0; i < count; ++i) {
            x_vector[i] += w[c] * gx * y[i];
            y_vector[i] += w[c] * gy * y[i];
        }
    }
}

// The coefficient vectors (as rc_project_cells: r, g, b, 3 order^2 floats) and their gradients
// (6 order^2 floats: r x, r y, g x, g y, b x, b y) of one record from its m x n cells: cells[c].xyz
// the radiance from cell c = j n + k's direction (rc_grid_stratum_direction), cells[c].w the
// distance to the surface the ray hit (INFINITY for a miss: no wall movement). Sums in cell order
// (deterministic).
RC_FUNC void rc_project_cells_with_gradients(RC_GLOBAL const float4* cells, int m, int n,
                                             uint key_lo, uint key_hi, uint record, int basis,
                                             int order, float* coefficients, float* gradients) {
    const int count = rc_sh_count(order);
    for (int i = 0; i < 3 * count; ++i) {
        coefficients[i] = 0.0f;
    }
    for (int i = 0; i < 6 * count; ++i) {
        gradients[i] = 0.0f;
    }
    const float weight = rc_uniform_stratum_weight(m, n);
    const float polar_wall = 2.0f * RC_PI / (float)n;  // 2 pi / N of the u_k term
    for (int c = 0; c < m * n; ++c) {
        const int j = c / n;
        const int k = c % n;
        const float3 d = rc_grid_stratum_direction(key_lo, key_hi, record, c, m, n);
        float y[RC_SH_MAX_COEFFICIENTS];
        rc_basis_eval(basis, d.x, d.y, d.z, order, y);
        const float4 cell = cells[c];
        for (int i = 0; i < count; ++i) {
            coefficients[i] += weight * cell.x * y[i];
            coefficients[count + i] += weight * cell.y * y[i];
            coefficients[2 * count + i] += weight * cell.z * y[i];
        }
        // The wall to the cell above (j - 1, k): moves by cos(theta_j-) / r per unit
        // displacement along u_k and sweeps sin(theta_j-) 2 pi / N of solid angle per radian.
        if (j > 0) {
            const float4 above = cells[c - n];
            const float cos_wall = 1.0f - (float)j / (float)m;
            const float sin_wall = sqrt(fmax(0.0f, 1.0f - cos_wall * cos_wall));
            const float factor = polar_wall * cos_wall * sin_wall / fmin(cell.w, above.w);
            const float phi = 2.0f * RC_PI * ((float)k + 0.5f) / (float)n;
            rc_gradient_accumulate(y, count, factor * (cell.xyz - above.xyz), cos(phi), sin(phi),
                                   gradients);
        }
        // The wall to the previous azimuthal cell (j, k - 1): at polar angle theta it moves by
        // 1 / (r sin theta) radians of azimuth per unit displacement along v_k-, so it sweeps
        // the integral of sin(theta) / (r sin(theta)) d theta = (theta_j+ - theta_j-) / r over
        // the row. The paper's 1 / (M r sin(theta_jk)) approximates this at the sample; the
        // integral has no 1 / sin(theta) at the pole, where the sample's polar angle would scale
        // the whole first row's term by a random factor.
        const float4 previous = cells[j * n + (k + n - 1) % n];
        const float row_width =
            acos(1.0f - (float)(j + 1) / (float)m) - acos(1.0f - (float)j / (float)m);
        const float factor = row_width / fmin(cell.w, previous.w);
        const float phi_wall = 2.0f * RC_PI * (float)k / (float)n;
        rc_gradient_accumulate(y, count, factor * (cell.xyz - previous.xyz), -sin(phi_wall),
                               cos(phi_wall), gradients);
    }
}
