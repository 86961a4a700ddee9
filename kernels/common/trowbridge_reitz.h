// The Trowbridge–Reitz (GGX) microfacet distribution, anisotropic, with its Smith masking
// function and the sampling of the normals visible from a direction (Walter et al., "Microfacet
// Models for Refraction through Rough Surfaces", EGSR 2007; Heitz, "Sampling the GGX
// Distribution of Visible Normals", JCGT 7(4), 2018; pbrt-v4 §9.6). Directions in the local frame
// (z = the macro-surface normal); alpha_x along the tangent, alpha_y along the bitangent.
#pragma once

#include "common/math.h"

typedef struct TrowbridgeReitz {
    float alpha_x;
    float alpha_y;
} TrowbridgeReitz;

// Below this roughness a lobe is rendered as its smooth (delta) limit, as pbrt-v4's
// EffectivelySmooth: the density would overflow single precision.
#define RC_SMOOTH_ALPHA 1e-3f

RC_FUNC bool rc_tr_effectively_smooth(TrowbridgeReitz d) {
    return fmax(d.alpha_x, d.alpha_y) < RC_SMOOTH_ALPHA;
}

// D(m), the density of microfacet normals per unit projected area (Walter et al. Eq. 33 with
// anisotropy; pbrt-v4 Eq. 9.16): 1 / (pi ax ay (mx^2/ax^2 + my^2/ay^2 + mz^2)^2).
RC_FUNC float rc_tr_d(TrowbridgeReitz d, float3 m) {
    if (m.z <= 0.0f) {
        return 0.0f;
    }
    const float x = m.x / d.alpha_x;
    const float y = m.y / d.alpha_y;
    const float s = x * x + y * y + m.z * m.z;
    return 1.0f / (RC_PI * d.alpha_x * d.alpha_y * s * s);
}

// Smith's Lambda(w) for the distribution (pbrt-v4 Eq. 9.22): (sqrt(1 + alpha^2 tan^2) - 1) / 2.
RC_FUNC float rc_tr_lambda(TrowbridgeReitz d, float3 w) {
    const float z2 = w.z * w.z;
    if (z2 == 0.0f) {
        return INFINITY;
    }
    const float ax = d.alpha_x * w.x;
    const float ay = d.alpha_y * w.y;
    return 0.5f * (sqrt(1.0f + (ax * ax + ay * ay) / z2) - 1.0f);
}

RC_FUNC float rc_tr_g1(TrowbridgeReitz d, float3 w) { return 1.0f / (1.0f + rc_tr_lambda(d, w)); }

// The height-correlated masking-shadowing function (pbrt-v4 Eq. 9.27).
RC_FUNC float rc_tr_g(TrowbridgeReitz d, float3 wo, float3 wi) {
    return 1.0f / (1.0f + rc_tr_lambda(d, wo) + rc_tr_lambda(d, wi));
}

// The density of normals visible from w (Heitz 2018, Eq. 1): G1(w) max(0, w.m) D(m) / |w.z|,
// m facing z+; for w below the surface (inside a dielectric) that of -w, the distribution being
// symmetric about z = 0.
RC_FUNC float rc_tr_visible_d(TrowbridgeReitz d, float3 w, float3 m) {
    const float w_m = w.z < 0.0f ? -dot(w, m) : dot(w, m);
    return rc_tr_g1(d, w) / fabs(w.z) * rc_tr_d(d, m) * fmax(0.0f, w_m);
}

// Samples a normal from rc_tr_visible_d for w, from (u1, u2) in [0,1)^2 (Heitz 2018, §3:
// stretch to the unit-roughness configuration, sample the projected hemisphere, unstretch).
RC_FUNC float3 rc_tr_sample_visible(TrowbridgeReitz d, float3 w, float u1, float u2) {
    float3 wh = normalize((float3)(d.alpha_x * w.x, d.alpha_y * w.y, w.z));
    if (wh.z < 0.0f) {
        wh = -wh;
    }
    const float3 t1 = wh.z < 0.99999f ? normalize(cross((float3)(0.0f, 0.0f, 1.0f), wh))
                                      : (float3)(1.0f, 0.0f, 0.0f);
    const float3 t2 = cross(wh, t1);
    const float r = sqrt(u1);
    const float phi = 2.0f * RC_PI * u2;
    const float px = r * cos(phi);
    float py = r * sin(phi);
    const float h = sqrt(fmax(0.0f, 1.0f - px * px));
    const float s = 0.5f * (1.0f + wh.z);
    py = (1.0f - s) * h + s * py;
    const float pz = sqrt(fmax(0.0f, 1.0f - px * px - py * py));
    const float3 nh = px * t1 + py * t2 + pz * wh;
    return normalize((float3)(d.alpha_x * nh.x, d.alpha_y * nh.y, fmax(1e-6f, nh.z)));
}
