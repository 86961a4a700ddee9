// A conductor: specular reflection weighted by the Fresnel reflectance of its complex index
// eta + i k per RGB channel, smooth (a delta lobe) or rough (the Torrance–Sparrow model over the
// Trowbridge–Reitz distribution, Walter et al. 2007, Eq. 20; pbrt-v4 §9.6.5, ConductorBxDF).
// Reflective only: wo and wi above the surface.
#pragma once

#include "common/bsdf_sample.h"
#include "common/fresnel.h"
#include "common/trowbridge_reitz.h"

// f(wo, wi) = D(m) F(wo.m) G(wo, wi) / (4 cos_o cos_i), m the half vector (0 for a smooth one).
RC_FUNC float3 rc_conductor_eval(TrowbridgeReitz d, float3 eta, float3 k, float3 wo, float3 wi) {
    if (rc_tr_effectively_smooth(d) || wo.z <= 0.0f || wi.z <= 0.0f) {
        return (float3)(0.0f);
    }
    const float3 sum = wo + wi;
    if (dot(sum, sum) == 0.0f) {
        return (float3)(0.0f);
    }
    const float3 m = normalize(sum);
    const float3 fresnel = rc_fresnel_conductor(fabs(dot(wo, m)), eta, k);
    return fresnel * (rc_tr_d(d, m) * rc_tr_g(d, wo, wi) / (4.0f * wo.z * wi.z));
}

// The density of rc_conductor_sample: the visible normals' density over 4 |wo.m| (the Jacobian
// of reflection, Walter et al. Eq. 14).
RC_FUNC float rc_conductor_pdf(TrowbridgeReitz d, float3 wo, float3 wi) {
    if (rc_tr_effectively_smooth(d) || wo.z <= 0.0f || wi.z <= 0.0f) {
        return 0.0f;
    }
    const float3 sum = wo + wi;
    if (dot(sum, sum) == 0.0f) {
        return 0.0f;
    }
    const float3 m = normalize(sum);
    return rc_tr_visible_d(d, wo, m) / (4.0f * fabs(dot(wo, m)));
}

RC_FUNC bool rc_conductor_sample(TrowbridgeReitz d, float3 eta, float3 k, float3 wo, float u1,
                                 float u2, BsdfSample* s) {
    if (wo.z <= 0.0f) {
        return false;
    }
    s->eta = 1.0f;
    if (rc_tr_effectively_smooth(d)) {
        s->wi = rc_reflect_local(wo);
        s->f = rc_fresnel_conductor(wo.z, eta, k) / wo.z;
        s->pdf = 1.0f;
        s->delta = true;
        return true;
    }
    const float3 m = rc_tr_sample_visible(d, wo, u1, u2);
    s->wi = rc_reflect_about(wo, m);
    if (s->wi.z <= 0.0f) {
        return false;
    }
    s->pdf = rc_tr_visible_d(d, wo, m) / (4.0f * fabs(dot(wo, m)));
    s->f = rc_conductor_eval(d, eta, k, wo, s->wi);
    s->delta = false;
    return s->pdf > 0.0f;
}
