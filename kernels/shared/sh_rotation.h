// Exact rotation of real spherical-harmonic coefficient vectors (spherical_harmonics.h's basis)
// by the recurrence of Ivanic and Ruedenberg, "Rotation Matrices for Real Spherical Harmonics.
// Direct Determination by Recursion", J. Phys. Chem. 100(15), 1996 (with the 1998 erratum), the
// SH rotation the course's "Rotation" slide and the HSH paper §4 ([IR96]) build on.
// The rotation is a 3x3 matrix R, row-major, that maps a direction's coordinates in the old frame
// to the new: d_new = R d_old. If f(d_old) = sum c_i Y_i(d_old), the rotated vector c' satisfies
// sum c'_i Y_i(R d) = sum c_i Y_i(d): the same function, expressed in the new frame.
// Band l's matrix is built from band l - 1's, so two bands are kept at a time (2 x 19^2 floats)
// and each band is applied as soon as it is known. Host (C++) and device (OpenCL C) run this code.
#pragma once

#include "compat.h"
#include "spherical_harmonics.h"

RC_SHARED_BEGIN

// Entry (m, n) of a band-l matrix, m, n in [-l, l].
RC_FUNC float rc_sh_band_at(const float* band, int l, int m, int n) {
    return band[(m + l) * (2 * l + 1) + (n + l)];
}

// IR96 eq. 6.1 (erratum): the function P of band l from the band-1 matrix r1 and band l - 1.
RC_FUNC float rc_sh_rotation_p(int i, int l, int a, int b, const float* r1, const float* prev) {
    if (b == l) {
        return rc_sh_band_at(r1, 1, i, 1) * rc_sh_band_at(prev, l - 1, a, l - 1) -
               rc_sh_band_at(r1, 1, i, -1) * rc_sh_band_at(prev, l - 1, a, -l + 1);
    }
    if (b == -l) {
        return rc_sh_band_at(r1, 1, i, 1) * rc_sh_band_at(prev, l - 1, a, -l + 1) +
               rc_sh_band_at(r1, 1, i, -1) * rc_sh_band_at(prev, l - 1, a, l - 1);
    }
    return rc_sh_band_at(r1, 1, i, 0) * rc_sh_band_at(prev, l - 1, a, b);
}

// Entry (m, n) of band l >= 2: M = u U + v V + w W (IR96 eq. 8.1; Table 3 gives U, V, W in
// terms of P), with u, v, w of Table 2 passed in (rc_sh_rotation_factors).
RC_FUNC float rc_sh_rotation_entry(int l, int m, int n, float u, float v, float w, const float* r1,
                                   const float* prev) {
    float value = 0.0f;
    if (u != 0.0f) {
        value += u * rc_sh_rotation_p(0, l, m, n, r1, prev);
    }
    if (v != 0.0f) {
        float big_v;
        if (m == 0) {
            big_v =
                rc_sh_rotation_p(1, l, 1, n, r1, prev) + rc_sh_rotation_p(-1, l, -1, n, r1, prev);
        } else if (m > 0) {
            const float delta = m == 1 ? 1.0f : 0.0f;
            big_v = rc_sh_rotation_p(1, l, m - 1, n, r1, prev) * sqrt(1.0f + delta) -
                    rc_sh_rotation_p(-1, l, -m + 1, n, r1, prev) * (1.0f - delta);
        } else {
            const float delta = m == -1 ? 1.0f : 0.0f;
            big_v = rc_sh_rotation_p(1, l, m + 1, n, r1, prev) * (1.0f - delta) +
                    rc_sh_rotation_p(-1, l, -m - 1, n, r1, prev) * sqrt(1.0f + delta);
        }
        value += v * big_v;
    }
    if (w != 0.0f) {
        const float big_w = m > 0 ? rc_sh_rotation_p(1, l, m + 1, n, r1, prev) +
                                        rc_sh_rotation_p(-1, l, -m - 1, n, r1, prev)
                                  : rc_sh_rotation_p(1, l, m - 1, n, r1, prev) -
                                        rc_sh_rotation_p(-1, l, -m + 1, n, r1, prev);
        value += w * big_w;
    }
    return value;
}

// IR96 Table 2, factored so a band costs O(l) square roots: u, v, w of entry (m, n) are
// u_m d_n, v_m d_n, w_m d_n with (delta = 1 for m = 0)
//   u_m = sqrt((l + m)(l - m)),  v_m = 1/2 sqrt((1 + delta)(l + |m| - 1)(l + |m|)) (1 - 2 delta),
//   w_m = -1/2 sqrt((l - |m| - 1)(l - |m|)) (1 - delta),
//   d_n = 1 / sqrt((l + n)(l - n)) for |n| < l, 1 / sqrt(2l (2l - 1)) for |n| = l;
// index m + l, n + l.
RC_FUNC void rc_sh_rotation_factors(int l, float* u, float* v, float* w, float* d) {
    for (int m = -l; m <= l; ++m) {
        const int am = m < 0 ? -m : m;
        const float delta = m == 0 ? 1.0f : 0.0f;
        u[m + l] = sqrt((float)((l + m) * (l - m)));
        v[m + l] =
            0.5f * sqrt((1.0f + delta) * (float)((l + am - 1) * (l + am))) * (1.0f - 2.0f * delta);
        w[m + l] = -0.5f * sqrt((float)((l - am - 1) * (l - am))) * (1.0f - delta);
        const float denominator =
            am < l ? (float)((l + m) * (l - m)) : (float)(2 * l * (2 * l - 1));
        d[m + l] = 1.0f / sqrt(denominator);
    }
}

// Band 1's matrix: Y_1^{-1}, Y_1^0, Y_1^1 are proportional to y, z, x, so its entry (m, n) is
// R's entry (axis of m, axis of n) with -1 -> y, 0 -> z, 1 -> x (IR96 eq. 7.4).
RC_FUNC void rc_sh_rotation_band1(const float* rotation, float* r1) {
    const int axis[3] = {1, 2, 0};
    for (int m = 0; m < 3; ++m) {
        for (int n = 0; n < 3; ++n) {
            r1[m * 3 + n] = rotation[axis[m] * 3 + axis[n]];
        }
    }
}

// Applies band l's matrix to band l of `vectors` coefficient vectors, vector v at
// coefficients[v * stride].
RC_FUNC void rc_sh_apply_band(const float* band, int l, float* coefficients, int vectors,
                              int stride) {
    const int size = 2 * l + 1;
    const int first = l * l;
    float rotated[RC_SH_MAX_BAND_SIZE];
    for (int v = 0; v < vectors; ++v) {
        float* c = coefficients + v * stride + first;
        for (int m = 0; m < size; ++m) {
            float sum = 0.0f;
            for (int n = 0; n < size; ++n) {
                sum += band[m * size + n] * c[n];
            }
            rotated[m] = sum;
        }
        for (int m = 0; m < size; ++m) {
            c[m] = rotated[m];
        }
    }
}

// Rotates, in place, `vectors` coefficient vectors of order `order` (<= RC_SH_MAX_ORDER) by
// `rotation` (row-major 3x3, d_new = R d_old); vector v starts at coefficients[v * stride].
// Band 0 is invariant.
RC_FUNC void rc_sh_rotate(const float* rotation, int order, float* coefficients, int vectors,
                          int stride) {
    if (order < 2) {
        return;
    }
    float r1[9];
    float band_a[RC_SH_MAX_BAND_SIZE * RC_SH_MAX_BAND_SIZE];
    float band_b[RC_SH_MAX_BAND_SIZE * RC_SH_MAX_BAND_SIZE];
    rc_sh_rotation_band1(rotation, r1);
    rc_sh_apply_band(r1, 1, coefficients, vectors, stride);
    for (int i = 0; i < 9; ++i) {
        band_a[i] = r1[i];
    }
    for (int l = 2; l < order; ++l) {
        // Band l - 1 is in band_a when l is even, in band_b when l is odd.
        const float* prev = (l & 1) ? band_b : band_a;
        float* band = (l & 1) ? band_a : band_b;
        float u[RC_SH_MAX_BAND_SIZE], v[RC_SH_MAX_BAND_SIZE], w[RC_SH_MAX_BAND_SIZE];
        float d[RC_SH_MAX_BAND_SIZE];
        rc_sh_rotation_factors(l, u, v, w, d);
        for (int m = -l; m <= l; ++m) {
            for (int n = -l; n <= l; ++n) {
                const float dn = d[n + l];
                band[(m + l) * (2 * l + 1) + (n + l)] = rc_sh_rotation_entry(
                    l, m, n, u[m + l] * dn, v[m + l] * dn, w[m + l] * dn, r1, prev);
            }
        }
        rc_sh_apply_band(band, l, coefficients, vectors, stride);
    }
}

RC_SHARED_END
