// The weight every record-based cache gives a record at a shading point (DESIGN.md §6.2, §6.4).
#pragma once

#include "shared/records.h"

// Ward's 1 / (d / R + sqrt(1 - n . n_i)) of a record at point p with normal n, shifted by -1/a so
// it falls to zero at the influence border (course, "Weighting Function Revisited"; d < a R),
// capped near the centre at max_weight. Zero for records "in front" of p (Ward et al. 1988,
// eq. 6). Radiance caching weights its records the same way (TVCG 2005 §4.4, the weight of eq. 12).
RC_FUNC float rc_record_weight(RC_GLOBAL const Record* record, float3 p, float3 n, float accuracy,
                               float max_weight) {
    const float3 offset = p - record->position.xyz;
    const float radius = record->radius;
    const float3 ni = record->normal.xyz;
    // Behind test: P_i in front of P, beyond a small tolerance of the influence radius.
    if (dot(offset, 0.5f * (n + ni)) < -1e-3f * accuracy * radius) {
        return 0.0f;
    }
    // sqrt(1 - n . n_i) as |n - n_i| / sqrt(2): equal for unit vectors, without the cancellation
    // of 1 - n . n_i in float when the normals are close.
    const float error = length(offset) / radius + length(n - ni) * 0.70710678f;
    if (error >= accuracy) {
        return 0.0f;
    }
    return fmin(1.0f / fmax(error, 1e-12f) - 1.0f / accuracy, max_weight);
}
