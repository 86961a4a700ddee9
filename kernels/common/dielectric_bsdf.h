// A dielectric interface (glass, water): Fresnel-weighted reflection and refraction, smooth (two
// delta lobes) or rough (Walter et al., "Microfacet Models for Refraction through Rough
// Surfaces", EGSR 2007, Eqs. 20–21, over the Trowbridge–Reitz distribution; pbrt-v4 §9.5 and
// §9.7, DielectricBxDF). eta is the index of the side below the local frame's z = 0 over the
// side above. Transmitted radiance is scaled by 1 / eta'^2 (radiance is not conserved across an
// interface, pbrt-v4 §9.5.2): a camera path's throughput; light-tracing callers undo it with
// BsdfSample.eta. `tint` scales both lobes (1: a clear interface).
#pragma once

#include "common/bsdf_sample.h"
#include "common/fresnel.h"
#include "common/trowbridge_reitz.h"

// Whether the interface is rendered smooth: effectively smooth roughness, or no interface at all
// (eta = 1, which pbrt-v4 also renders as pure transmission).
RC_FUNC bool rc_dielectric_smooth(TrowbridgeReitz d, float eta) {
    return eta == 1.0f || rc_tr_effectively_smooth(d);
}

// The generalised half vector of wo and wi (Walter et al. Eq. 16), facing z+, with eta' (the
// relative index wi's side over wo's side, 1 for a reflection); false where it is undefined or a
// microfacet would face away from either direction.
RC_FUNC bool rc_dielectric_half_vector(float eta, float3 wo, float3 wi, float3* m, float* etap) {
    const bool reflect = wo.z * wi.z > 0.0f;
    *etap = reflect ? 1.0f : (wo.z > 0.0f ? eta : 1.0f / eta);
    float3 h = wi * *etap + wo;
    if (wi.z == 0.0f || wo.z == 0.0f || dot(h, h) == 0.0f) {
        return false;
    }
    h = normalize(h);
    if (h.z < 0.0f) {
        h = -h;
    }
    *m = h;
    return dot(h, wi) * wi.z >= 0.0f && dot(h, wo) * wo.z >= 0.0f;
}

// f(wo, wi): reflection D F G / |4 cos_o cos_i|, transmission
// D (1 - F) G |wi.m wo.m| / (|cos_o cos_i| (wi.m + wo.m / eta')^2) / eta'^2 (0 when smooth).
RC_FUNC float rc_dielectric_eval(TrowbridgeReitz d, float eta, float3 wo, float3 wi) {
    float3 m;
    float etap;
    if (rc_dielectric_smooth(d, eta) || !rc_dielectric_half_vector(eta, wo, wi, &m, &etap)) {
        return 0.0f;
    }
    const float fresnel = rc_fresnel_dielectric(dot(wo, m), eta);
    const float dg = rc_tr_d(d, m) * rc_tr_g(d, wo, wi);
    if (etap == 1.0f) {
        return dg * fresnel / fabs(4.0f * wo.z * wi.z);
    }
    const float denominator = dot(wi, m) + dot(wo, m) / etap;
    return dg * (1.0f - fresnel) * fabs(dot(wi, m) * dot(wo, m)) /
           (fabs(wo.z * wi.z) * denominator * denominator) / (etap * etap);
}

// The density of rc_dielectric_sample: the visible normals' density times the chosen lobe's
// probability (F or 1 - F) and the Jacobian of reflection (1 / (4 |wo.m|)) or refraction
// (|wi.m| / (wi.m + wo.m / eta')^2, Walter et al. Eq. 17).
RC_FUNC float rc_dielectric_pdf(TrowbridgeReitz d, float eta, float3 wo, float3 wi) {
    float3 m;
    float etap;
    if (rc_dielectric_smooth(d, eta) || !rc_dielectric_half_vector(eta, wo, wi, &m, &etap)) {
        return 0.0f;
    }
    const float fresnel = rc_fresnel_dielectric(dot(wo, m), eta);
    const float visible = rc_tr_visible_d(d, wo, m);
    if (etap == 1.0f) {
        return visible / (4.0f * fabs(dot(wo, m))) * fresnel;
    }
    const float denominator = dot(wi, m) + dot(wo, m) / etap;
    return visible * fabs(dot(wi, m)) / (denominator * denominator) * (1.0f - fresnel);
}

// Refraction of wo through the interface with normal m (z+ facing), from either side: the
// transmitted direction and eta' (the relative index crossed).
RC_FUNC bool rc_dielectric_refract(float3 wo, float3 m, float eta, float3* wi, float* etap) {
    if (dot(wo, m) < 0.0f) {
        eta = 1.0f / eta;
        m = -m;
    }
    *etap = eta;
    return rc_refract(wo, m, eta, wi);
}

// Smooth interface: reflection with probability F, else refraction (pbrt-v4 §9.5.1).
RC_FUNC bool rc_dielectric_sample_smooth(float eta, float3 wo, float u_lobe, BsdfSample* s) {
    const float fresnel = rc_fresnel_dielectric(wo.z, eta);
    s->delta = true;
    if (u_lobe < fresnel) {
        s->wi = rc_reflect_local(wo);
        s->f = (float3)(fresnel / fabs(s->wi.z));
        s->pdf = fresnel;
        s->eta = 1.0f;
        return fresnel > 0.0f;
    }
    if (!rc_dielectric_refract(wo, (float3)(0.0f, 0.0f, 1.0f), eta, &s->wi, &s->eta)) {
        return false;
    }
    s->f = (float3)((1.0f - fresnel) / fabs(s->wi.z) / (s->eta * s->eta));
    s->pdf = 1.0f - fresnel;
    return s->wi.z != 0.0f;
}

RC_FUNC bool rc_dielectric_sample(TrowbridgeReitz d, float eta, float3 tint, float3 wo,
                                  float u_lobe, float u1, float u2, BsdfSample* s) {
    if (wo.z == 0.0f) {
        return false;
    }
    if (rc_dielectric_smooth(d, eta)) {
        const bool sampled = rc_dielectric_sample_smooth(eta, wo, u_lobe, s);
        s->f *= tint;
        return sampled;
    }
    // A visible normal for |wo| (the distribution is symmetric about z = 0).
    const float sign = wo.z > 0.0f ? 1.0f : -1.0f;
    const float3 m = sign * rc_tr_sample_visible(d, sign * wo, u1, u2);
    const float fresnel = rc_fresnel_dielectric(dot(wo, m), eta);
    s->delta = false;
    s->eta = 1.0f;
    if (u_lobe < fresnel) {
        s->wi = rc_reflect_about(wo, m);
        if (s->wi.z * wo.z <= 0.0f) {
            return false;
        }
    } else {
        float etap;
        if (!rc_dielectric_refract(wo, m, eta, &s->wi, &etap) || s->wi.z * wo.z >= 0.0f) {
            return false;
        }
        s->eta = etap;
    }
    s->pdf = rc_dielectric_pdf(d, eta, wo, s->wi);
    s->f = tint * rc_dielectric_eval(d, eta, wo, s->wi);
    return s->pdf > 0.0f;
}
