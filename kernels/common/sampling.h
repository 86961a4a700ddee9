// Sampling of directions.
#pragma once

#include "common/math.h"
#include "shared/types.h"

// Point on the unit disk from (u1, u2) in [0,1)^2, area-preserving: Shirley and Chiu, "A Low
// Distortion Map Between Disk and Square", JGT 2(3), 1997 (the concentric map).
RC_FUNC float2 rc_concentric_disk(float u1, float u2) {
    const float a = 2.0f * u1 - 1.0f;
    const float b = 2.0f * u2 - 1.0f;
    if (a == 0.0f && b == 0.0f) {
        return (float2)(0.0f, 0.0f);
    }
    const float kQuarterPi = 0.78539816339744831f;
    const bool by_a = fabs(a) > fabs(b);
    const float r = by_a ? a : b;
    const float phi = by_a ? kQuarterPi * (b / a) : 2.0f * kQuarterPi - kQuarterPi * (a / b);
    float cos_phi;
    const float sin_phi = sincos(phi, &cos_phi);  // one argument reduction for both
    return (float2)(r * cos_phi, r * sin_phi);
}

// Cosine-distributed direction about +z (Malley's method: lift the disk point to the
// hemisphere); pdf = cos(theta) / pi.
RC_FUNC float3 rc_cosine_hemisphere(float u1, float u2) {
    const float2 d = rc_concentric_disk(u1, u2);
    const float z = sqrt(fmax(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return (float3)(d.x, d.y, z);
}

// Orthonormal basis (t, b) completing the unit vector n: Duff et al., "Building an Orthonormal
// Basis, Revisited", JCGT 6(1), 2017.
RC_FUNC void rc_orthonormal_basis(float3 n, float3* t, float3* b) {
    const float sign = copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    *t = (float3)(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = (float3)(c, sign + n.y * n.y * a, -n.y);
}

// v, given in the frame whose z axis is n, in world coordinates.
RC_FUNC float3 rc_to_world(float3 v, float3 n) {
    float3 t, b;
    rc_orthonormal_basis(n, &t, &b);
    return v.x * t + v.y * b + v.z * n;
}

// A unit direction about axis `n` at polar cosine cos_theta and azimuth 2 pi u.
RC_FUNC float3 rc_direction_about(float3 n, float cos_theta, float u) {
    const float sin_theta = sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * RC_PI * u;
    return rc_to_world((float3)(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta), n);
}
