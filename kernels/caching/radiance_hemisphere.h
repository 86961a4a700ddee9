// The hemisphere sampling of a radiance record (DESIGN.md §6.4): M x N strata of equal solid
// angle, one jittered direction each, uniform density (course, "Incoming Radiance Computation";
// TVCG 2005 §4.2 eq. 4). Directions are in the record's frame (z = its normal).
#pragma once

#include "common/math.h"
#include "shared/rng.h"

// Direction of stratum (j, k) of an m x n division jittered by (u1, u2) in [0, 1)^2:
//   cos(theta) = 1 - (j + u1) / m,  phi = 2 pi (k + u2) / n.
// The course's slide writes theta = asin((j + X) / M), which is not uniform in solid angle (its
// density is cos(theta) / (2 pi sin(theta))) and so does not match the uniform weight 2 pi / (MN)
// of its quadrature; equal strata in cos(theta) are what that weight needs.
RC_FUNC float3 rc_uniform_stratum_direction(int j, int k, int m, int n, float u1, float u2) {
    const float cos_theta = 1.0f - ((float)j + u1) / (float)m;
    const float sin_theta = sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * RC_PI * ((float)k + u2) / (float)n;
    return (float3)(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

// The solid angle of one stratum, the quadrature weight of each sample: 2 pi / (m n).
RC_FUNC float rc_uniform_stratum_weight(int m, int n) { return 2.0f * RC_PI / ((float)m * n); }

// The jitter of cell c = j n + k of record `record`: words 0 and 1 of the random stream
// (key, record, cell), so the cell kernel that traces the ray and the projection that weights its
// radiance draw the same direction without storing it.
RC_FUNC void rc_stratum_jitter(uint key_lo, uint key_hi, uint record, uint cell, float* u1,
                               float* u2) {
    RngStream stream = rc_rng_stream(key_lo, key_hi, record, cell);
    *u1 = rc_rng_next_float(&stream);
    *u2 = rc_rng_next_float(&stream);
}

// The direction of cell `cell` of record `record` (rc_stratum_jitter's jitter).
RC_FUNC float3 rc_stratum_direction(uint key_lo, uint key_hi, uint record, int cell, int m, int n) {
    float u1, u2;
    rc_stratum_jitter(key_lo, key_hi, record, (uint)cell, &u1, &u2);
    return rc_uniform_stratum_direction(cell / n, cell % n, m, n, u1, u2);
}

// The direction of cell `cell` = j n + k of record `record` on a jittered grid: one polar jitter
// per row j (word 0 of cell (j, 0)'s stream) and one azimuthal jitter per column k (word 1 of cell
// (0, k)'s stream), so cells (j, k) and (j, k - 1) differ only in azimuth and cells (j, k) and
// (j - 1, k) only in polar angle. The translational gradients (rc_gradients.h) difference the
// radiance of such neighbours across the wall between them (Ward and Heckbert's cell-wall
// argument assumes this grid); with independent jitter per cell the azimuthal differences near
// the pole would mix in polar changes, amplified by 1 / sin(theta). Each cell's direction is
// still uniform within its stratum, so the projection stays unbiased.
RC_FUNC float3 rc_grid_stratum_direction(uint key_lo, uint key_hi, uint record, int cell, int m,
                                         int n) {
    const int j = cell / n;
    const int k = cell % n;
    float u1, u2, unused;
    rc_stratum_jitter(key_lo, key_hi, record, (uint)(j * n), &u1, &unused);
    rc_stratum_jitter(key_lo, key_hi, record, (uint)k, &unused, &u2);
    return rc_uniform_stratum_direction(j, k, m, n, u1, u2);
}
