// Fast exact rotation of real SH coefficient vectors by the zxzxz factorization (Kautz, Sloan
// and Snyder, "Fast, Arbitrary BRDF Shading for Low-Frequency Lighting Using Spherical
// Harmonics", EGWR 2002, §5; the course's "Rotation" slide names the rotation as the bottleneck
// of radiance-cache interpolation). Any rotation is R = Rz(alpha) Ry(beta) Rz(gamma) (ZYZ Euler
// angles) and Ry(beta) = Rx(-90) Rz(beta) Rx(+90), so
//   D(R) = D(Rz alpha) D(Rx -90) D(Rz beta) D(Rx +90) D(Rz gamma):
// three rotations about z (closed form: band l's (m, -m) pairs turn by m times the angle) and two
// fixed matrices, D(Rx +90) and its transpose D(Rx -90), tabulated once (rc_sh_x90_table, built
// from the exact Ivanic-Ruedenberg rotation of sh_rotation.h). The cosines and sines of m alpha
// come from (cos alpha, sin alpha) by complex multiplication: no trigonometric call.
// Same convention as rc_sh_rotate: d_new = R d_old, sum c'_i Y_i(R d) = sum c_i Y_i(d).
// Host (C++) and device (OpenCL C) run this code.
#pragma once

#include "compat.h"
#include "sh_rotation.h"
#include "spherical_harmonics.h"

RC_SHARED_BEGIN

// Floats of the table of band matrices of D(Rx +90) for bands 0 .. RC_SH_MAX_ORDER - 1:
// sum over l of (2l + 1)^2 = n (2n - 1)(2n + 1) / 3 for n = RC_SH_MAX_ORDER.
#define RC_SH_X90_TABLE_SIZE \
    (RC_SH_MAX_ORDER * (2 * RC_SH_MAX_ORDER - 1) * (2 * RC_SH_MAX_ORDER + 1) / 3)

// Offset of band l's (2l + 1)^2 matrix (row-major, entry (m, n) at (m + l)(2l + 1) + n + l).
RC_FUNC int rc_sh_x90_band_offset(int l) { return l * (2 * l - 1) * (2 * l + 1) / 3; }

// Fills `table` (RC_SH_X90_TABLE_SIZE floats) with D(Rx +90): column j of band l is the exact
// rotation of the unit vector of coefficient l(l + 1) + j - l (run once, on the host).
RC_FUNC void rc_sh_x90_table(float* table) {
    // Rx(+90): x -> x, y -> z, z -> -y.
    const float rotation[9] = {1.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f, 0.0f, 1.0f, 0.0f};
    for (int l = 0; l < RC_SH_MAX_ORDER; ++l) {
        const int size = 2 * l + 1;
        for (int column = 0; column < size; ++column) {
            float c[RC_SH_MAX_COEFFICIENTS];
            for (int i = 0; i < RC_SH_MAX_COEFFICIENTS; ++i) {
                c[i] = 0.0f;
            }
            c[l * l + column] = 1.0f;
            rc_sh_rotate(rotation, l + 1, c, 1, RC_SH_MAX_COEFFICIENTS);
            for (int row = 0; row < size; ++row) {
                table[rc_sh_x90_band_offset(l) + row * size + column] = c[l * l + row];
            }
        }
    }
}

// Rotation about z by the angle with cosine `c1` and sine `s1`, in place on `vectors` vectors:
// c'_m = c_m cos(m a) - c_-m sin(m a), c'_-m = c_-m cos(m a) + c_m sin(m a) (Y_l^m ~ cos(m phi),
// Y_l^-m ~ sin(m phi), m > 0).
RC_FUNC void rc_sh_rotate_z(float c1, float s1, int order, float* coefficients, int vectors,
                            int stride) {
    float cosines[RC_SH_MAX_ORDER];
    float sines[RC_SH_MAX_ORDER];
    cosines[0] = 1.0f;
    sines[0] = 0.0f;
    for (int m = 1; m < order; ++m) {
        cosines[m] = cosines[m - 1] * c1 - sines[m - 1] * s1;
        sines[m] = sines[m - 1] * c1 + cosines[m - 1] * s1;
    }
    for (int v = 0; v < vectors; ++v) {
        float* c = coefficients + v * stride;
        for (int l = 1; l < order; ++l) {
            const int centre = l * (l + 1);
            for (int m = 1; m <= l; ++m) {
                const float positive = c[centre + m];
                const float negative = c[centre - m];
                c[centre + m] = positive * cosines[m] - negative * sines[m];
                c[centre - m] = negative * cosines[m] + positive * sines[m];
            }
        }
    }
}

// D(Rx +90) (transpose = 0) or D(Rx -90) (transpose = 1) from the table, in place.
RC_FUNC void rc_sh_rotate_x90(RC_GLOBAL const float* table, int transpose, int order,
                              float* coefficients, int vectors, int stride) {
    for (int l = 1; l < order; ++l) {
        const int size = 2 * l + 1;
        RC_GLOBAL const float* band = table + rc_sh_x90_band_offset(l);
        const int row_step = transpose ? 1 : size;
        const int column_step = transpose ? size : 1;
        for (int v = 0; v < vectors; ++v) {
            float* c = coefficients + v * stride + l * l;
            float rotated[RC_SH_MAX_BAND_SIZE];
            for (int m = 0; m < size; ++m) {
                float sum = 0.0f;
                for (int n = 0; n < size; ++n) {
                    sum += band[m * row_step + n * column_step] * c[n];
                }
                rotated[m] = sum;
            }
            for (int m = 0; m < size; ++m) {
                c[m] = rotated[m];
            }
        }
    }
}

// ZYZ Euler angles of R = Rz(alpha) Ry(beta) Rz(gamma) as cosines and sines ([0] cos, [1] sin):
// R's third column is (cos alpha sin beta, sin alpha sin beta, cos beta); gamma is read from
// row 1 of Rz(-alpha) R = Ry(beta) Rz(gamma), which is (sin gamma, cos gamma, 0) whatever beta,
// so the angles stay consistent when sin beta is small (alpha = 0 there).
RC_FUNC void rc_sh_zyz_angles(const float* r, float* alpha, float* beta, float* gamma) {
    const float sin_beta = sqrt(r[2] * r[2] + r[5] * r[5]);
    alpha[0] = 1.0f;
    alpha[1] = 0.0f;
    if (sin_beta > 1e-6f) {
        alpha[0] = r[2] / sin_beta;
        alpha[1] = r[5] / sin_beta;
    }
    beta[0] = r[8];
    beta[1] = alpha[0] * r[2] + alpha[1] * r[5];
    const float sin_gamma = -alpha[1] * r[0] + alpha[0] * r[3];
    const float cos_gamma = -alpha[1] * r[1] + alpha[0] * r[4];
    const float gamma_norm = sqrt(sin_gamma * sin_gamma + cos_gamma * cos_gamma);
    gamma[0] = cos_gamma / gamma_norm;
    gamma[1] = sin_gamma / gamma_norm;
    const float beta_norm = sqrt(beta[0] * beta[0] + beta[1] * beta[1]);
    beta[0] /= beta_norm;
    beta[1] /= beta_norm;
}

// Rotates, in place, `vectors` coefficient vectors of order `order` (<= RC_SH_MAX_ORDER) by
// `rotation` (row-major 3x3, d_new = R d_old), vector v at coefficients[v * stride]; `x90` is
// rc_sh_x90_table's table. Same result as rc_sh_rotate.
RC_FUNC void rc_sh_rotate_zxz(const float* rotation, RC_GLOBAL const float* x90, int order,
                              float* coefficients, int vectors, int stride) {
    if (order < 2) {
        return;
    }
    float alpha[2], beta[2], gamma[2];
    rc_sh_zyz_angles(rotation, alpha, beta, gamma);
    // Frames with the same normal (a flat surface): R is a rotation about z by gamma (alpha = 0
    // there), O(n^2) and no dense band.
    if (beta[0] > 0.0f && beta[1] <= 1e-6f && beta[1] >= -1e-6f) {
        rc_sh_rotate_z(gamma[0], gamma[1], order, coefficients, vectors, stride);
        return;
    }
    rc_sh_rotate_z(gamma[0], gamma[1], order, coefficients, vectors, stride);
    rc_sh_rotate_x90(x90, 0, order, coefficients, vectors, stride);
    rc_sh_rotate_z(beta[0], beta[1], order, coefficients, vectors, stride);
    rc_sh_rotate_x90(x90, 1, order, coefficients, vectors, stride);
    rc_sh_rotate_z(alpha[0], alpha[1], order, coefficients, vectors, stride);
}

RC_SHARED_END
