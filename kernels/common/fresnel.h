// Fresnel reflectance of smooth interfaces: unpolarised light at a dielectric interface and at a
// conductor with a complex index of refraction eta + i k (pbrt-v4 §9.3.4–9.3.6; Born and Wolf,
// "Principles of Optics", §1.5.2 and §14.2).
#pragma once

#include "shared/types.h"

// Refraction of w about the unit normal n (w and n on one side, cos_i = dot(n, w) >= 0) into a
// medium of relative index eta (transmitted side over incident side), Snell's law in vector form
// (pbrt-v4 Eq. 9.19). False on total internal reflection.
RC_FUNC bool rc_refract(float3 w, float3 n, float eta, float3* wt) {
    const float cos_i = dot(n, w);
    const float sin2_t = fmax(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) {
        return false;
    }
    const float cos_t = sqrt(1.0f - sin2_t);
    *wt = -w / eta + (cos_i / eta - cos_t) * n;
    return true;
}

// Reflectance of a dielectric interface for light arriving at cos_i from the side the normal
// points to (cos_i < 0: from the other side), eta the index of the far side over the near side
// (pbrt-v4 Eqs. 9.24–9.26): the mean of the parallel and perpendicular amplitude ratios squared;
// 1 under total internal reflection.
RC_FUNC float rc_fresnel_dielectric(float cos_i, float eta) {
    cos_i = clamp(cos_i, -1.0f, 1.0f);
    if (cos_i < 0.0f) {
        eta = 1.0f / eta;
        cos_i = -cos_i;
    }
    const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) {
        return 1.0f;
    }
    const float cos_t = sqrt(fmax(0.0f, 1.0f - sin2_t));
    const float parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (parallel * parallel + perpendicular * perpendicular);
}

// Complex numbers as float2 (re, im), for the conductor's Fresnel equations.
RC_FUNC float2 rc_complex_mul(float2 a, float2 b) {
    return (float2)(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

RC_FUNC float2 rc_complex_div(float2 a, float2 b) {
    const float scale = 1.0f / (b.x * b.x + b.y * b.y);
    return (float2)((a.x * b.x + a.y * b.y) * scale, (a.y * b.x - a.x * b.y) * scale);
}

RC_FUNC float rc_complex_norm(float2 a) { return a.x * a.x + a.y * a.y; }

// The principal square root of a complex number.
RC_FUNC float2 rc_complex_sqrt(float2 z) {
    const float magnitude = sqrt(rc_complex_norm(z));
    if (magnitude == 0.0f) {
        return (float2)(0.0f);
    }
    const float t1 = sqrt(0.5f * (magnitude + fabs(z.x)));
    const float t2 = 0.5f * z.y / t1;
    return z.x >= 0.0f ? (float2)(t1, t2) : (float2)(fabs(t2), copysign(t1, z.y));
}

// Reflectance of a conductor of complex index eta + i k for light at cos_i >= 0 (the dielectric
// Fresnel equations with a complex index, pbrt-v4 Eq. 9.26 and §9.3.6).
RC_FUNC float rc_fresnel_complex(float cos_i, float eta, float k) {
    cos_i = clamp(cos_i, 0.0f, 1.0f);
    const float2 index = (float2)(eta, k);
    const float2 sin2_t =
        rc_complex_div((float2)(1.0f - cos_i * cos_i, 0.0f), rc_complex_mul(index, index));
    const float2 cos_t = rc_complex_sqrt((float2)(1.0f - sin2_t.x, -sin2_t.y));
    const float2 index_cos_i = index * cos_i;
    const float2 parallel = rc_complex_div(index_cos_i - cos_t, index_cos_i + cos_t);
    const float2 index_cos_t = rc_complex_mul(index, cos_t);
    const float2 perpendicular =
        rc_complex_div((float2)(cos_i, 0.0f) - index_cos_t, (float2)(cos_i, 0.0f) + index_cos_t);
    return 0.5f * (rc_complex_norm(parallel) + rc_complex_norm(perpendicular));
}

RC_FUNC float3 rc_fresnel_conductor(float cos_i, float3 eta, float3 k) {
    return (float3)(rc_fresnel_complex(cos_i, eta.x, k.x), rc_fresnel_complex(cos_i, eta.y, k.y),
                    rc_fresnel_complex(cos_i, eta.z, k.z));
}
