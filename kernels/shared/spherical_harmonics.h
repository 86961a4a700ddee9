// Real spherical harmonics (SH) and the hemispherical harmonics (HSH) of Gautron et al., "A Novel
// Hemispherical Basis for Accurate and Efficient Rendering" (EGSR 2004; the course reprints it),
// up to order RC_SH_MAX_ORDER. Order n means bands l = 0 .. n - 1: n^2 functions, function
// (l, m) at index l (l + 1) + m (course, "Incoming Radiance Representation").
// The same code runs on the host (C++) and on the device (OpenCL C): plain floats, private
// arrays, no vector types.
#pragma once

#include "compat.h"

#ifndef __OPENCL_VERSION__
#include <cmath>
namespace rc::shared {
using std::sqrt;  // the float overload, as OpenCL C's sqrt
}
#endif

// The highest order radiance caching uses (course: "we use order up to 10").
#define RC_SH_MAX_ORDER 10
#define RC_SH_MAX_COEFFICIENTS (RC_SH_MAX_ORDER * RC_SH_MAX_ORDER)
// Functions in the largest band, 2 (n_max - 1) + 1.
#define RC_SH_MAX_BAND_SIZE (2 * RC_SH_MAX_ORDER - 1)

// Which basis a coefficient vector refers to.
#define RC_BASIS_SH 0
#define RC_BASIS_HSH 1

RC_SHARED_BEGIN

// The recurrence's constants (see rc_sh_eval), in single precision: Q_m^m, sqrt(2m + 3), and
// a_l^m, b_l^m at [l RC_SH_MAX_ORDER + m] (zero where unused). tests/shared/sh_basis_test.cpp
// checks every entry against its formula.
// clang-format off
RC_CONSTANT const float rc_sh_diagonal[RC_SH_MAX_ORDER] = {
    0.282094792f, 0.345494149f, 0.386274202f, 0.417223824f, 0.442532692f,
    0.464132203f, 0.483084114f, 0.500039564f, 0.515428984f, 0.529552941f,
};
RC_CONSTANT const float rc_sh_subdiagonal[RC_SH_MAX_ORDER] = {
    1.73205081f, 2.23606798f, 2.64575131f, 3.0f, 3.31662479f,
    3.60555128f, 3.87298335f, 4.12310563f, 4.35889894f, 4.58257569f,
};
RC_CONSTANT const float rc_sh_recurrence_a[RC_SH_MAX_COEFFICIENTS] = {
    0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    1.93649167f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    1.97202659f, 2.09165007f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    1.98431348f, 2.04939015f, 2.29128785f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    1.98997487f, 2.0310096f, 2.17124059f, 2.48746859f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    1.99304346f, 2.02131499f, 2.11394182f, 2.30136835f, 2.67394839f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    1.99489143f, 2.01556444f, 2.081666f, 2.20794022f, 2.43086217f, 2.85043856f, 0.0f, 0.0f, 0.0f, 0.0f,
    1.99608993f, 2.01186954f, 2.06155281f, 2.15322169f, 2.30488611f, 2.55704156f, 3.01780431f, 0.0f, 0.0f, 0.0f,
    1.9969112f, 2.00935313f, 2.04812236f, 2.11804417f, 2.22917715f, 2.40163635f, 2.67913751f, 3.17706626f, 0.0f, 0.0f,
};
RC_CONSTANT const float rc_sh_recurrence_b[RC_SH_MAX_COEFFICIENTS] = {
    0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.577350269f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.516397779f, 0.447213595f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.507092553f, 0.478091444f, 0.377964473f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.503952631f, 0.487950036f, 0.43643578f, 0.333333333f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.502518908f, 0.492365964f, 0.460566186f, 0.402015126f, 0.301511345f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.501745206f, 0.494727445f, 0.473049917f, 0.434524095f, 0.373978796f, 0.277350098f, 0.0f, 0.0f, 0.0f, 0.0f,
    0.501280412f, 0.496138938f, 0.480384461f, 0.452910814f, 0.411376676f, 0.350823208f, 0.25819889f, 0.0f, 0.0f, 0.0f,
    0.500979433f, 0.497050122f, 0.48507125f, 0.464420364f, 0.433860916f, 0.391076944f, 0.331366748f, 0.242535625f, 0.0f, 0.0f,
};
// clang-format on

RC_FUNC int rc_sh_index(int l, int m) { return l * (l + 1) + m; }

RC_FUNC int rc_sh_count(int order) { return order * order; }

// Y_l^m at the unit direction (x, y, z) into out[0 .. order^2), order <= RC_SH_MAX_ORDER.
// The HSH paper's eq. 3 and 4:
//   Y_l^m = sqrt(2) K_l^m cos(m phi) P_l^m(cos theta)     m > 0
//   Y_l^m = sqrt(2) K_l^m sin(-m phi) P_l^-m(cos theta)   m < 0
//   Y_l^0 = K_l^0 P_l^0(cos theta),  K_l^m = sqrt((2l + 1) (l - |m|)! / (4 pi (l + |m|)!)),
// without the Condon-Shortley phase (-1)^m of its Appendix B eq. 28 (the convention of Ivanic
// and Ruedenberg's rotation recurrence, sh_rotation.h; it flips the sign of odd-m functions
// only). Evaluated by the stable recurrences of Appendix B (eq. 27-29) on the normalized
// polynomials Q_l^m = K_l^m P_l^m / sin^m(theta), which avoid the factorials:
//   Q_m^m     = sqrt(1 / 4pi) prod_{k=1..m} sqrt((2k + 1) / 2k)           (eq. 28)
//   Q_m+1^m   = sqrt(2m + 3) z Q_m^m                                       (eq. 29)
//   Q_l^m     = a_l^m (z Q_l-1^m - b_l^m Q_l-2^m),                         (eq. 27)
//               a = sqrt((4l^2 - 1) / (l^2 - m^2)), b = sqrt(((l-1)^2 - m^2) / (4(l-1)^2 - 1)),
// the constants read from the tables above, and sin^m(theta) cos(m phi), sin^m(theta) sin(m phi)
// as the real and imaginary parts of (x + i y)^m: no square root, division or trigonometric
// function per evaluation.
RC_FUNC void rc_sh_eval(float x, float y, float z, int order, float* out) {
    float cos_m = 1.0f;  // sin^m(theta) cos(m phi)
    float sin_m = 0.0f;  // sin^m(theta) sin(m phi)
    for (int m = 0; m < order; ++m) {
        if (m > 0) {
            const float c = x * cos_m - y * sin_m;
            sin_m = x * sin_m + y * cos_m;
            cos_m = c;
        }
        const float scale_cos = m == 0 ? 1.0f : 1.41421356237309505f * cos_m;
        const float scale_sin = 1.41421356237309505f * sin_m;
        float q_prev = 0.0f;
        float q = rc_sh_diagonal[m];
        for (int l = m; l < order; ++l) {
            if (l == m + 1) {
                q_prev = q;
                q = rc_sh_subdiagonal[m] * z * q;
            } else if (l > m + 1) {
                const int at = l * RC_SH_MAX_ORDER + m;
                const float next =
                    rc_sh_recurrence_a[at] * (z * q - rc_sh_recurrence_b[at] * q_prev);
                q_prev = q;
                q = next;
            }
            out[rc_sh_index(l, m)] = q * scale_cos;
            if (m > 0) {
                out[rc_sh_index(l, -m)] = q * scale_sin;
            }
        }
    }
}

// H_l^m at the unit direction (x, y, z), z >= 0, into out[0 .. order^2): the HSH paper's eq. 8
// and 9, H_l^m = sqrt(2) K_l^m trig(m phi) P_l^|m|(2 cos theta - 1) (its normalization
// K~ = sqrt(2) K), i.e. sqrt(2) Y_l^m at the direction with the same azimuth and the shifted
// polar cosine z' = 2z - 1 (eq. 5, 6). That direction's sin(theta') / sin(theta) is
// sqrt(4z(1 - z) / (1 - z^2)) = 2 sqrt(z / (1 + z)), finite at the pole. Zero below the horizon,
// where the basis is not defined.
RC_FUNC void rc_hsh_eval(float x, float y, float z, int order, float* out) {
    const int count = rc_sh_count(order);
    if (z < 0.0f) {
        for (int i = 0; i < count; ++i) {
            out[i] = 0.0f;
        }
        return;
    }
    const float scale = 2.0f * sqrt(z / (1.0f + z));
    rc_sh_eval(x * scale, y * scale, 2.0f * z - 1.0f, order, out);
    for (int i = 0; i < count; ++i) {
        out[i] *= 1.41421356237309505f;
    }
}

// The basis functions of `basis` (RC_BASIS_SH or RC_BASIS_HSH) at (x, y, z).
RC_FUNC void rc_basis_eval(int basis, float x, float y, float z, int order, float* out) {
    if (basis == RC_BASIS_HSH) {
        rc_hsh_eval(x, y, z, order, out);
    } else {
        rc_sh_eval(x, y, z, order, out);
    }
}

RC_SHARED_END
