// A thin dielectric sheet (a window pane): light reflects off it or passes straight through,
// the sheet's internal reflections summed in closed form (pbrt-v4 §9.5.3, ThinDielectricBxDF):
// R' = R + T^2 R / (1 - R^2), T' = 1 - R', R the single interface's Fresnel reflectance.
// Two delta lobes; `tint` scales both.
#pragma once

#include "common/bsdf_sample.h"
#include "common/fresnel.h"

RC_FUNC float rc_thin_dielectric_reflectance(float cos_o, float eta) {
    float r = rc_fresnel_dielectric(fabs(cos_o), eta);
    const float t = 1.0f - r;
    if (r < 1.0f) {
        r += t * t * r / (1.0f - r * r);
    }
    return r;
}

RC_FUNC bool rc_thin_dielectric_sample(float eta, float3 tint, float3 wo, float u_lobe,
                                       BsdfSample* s) {
    if (wo.z == 0.0f) {
        return false;
    }
    const float r = rc_thin_dielectric_reflectance(wo.z, eta);
    s->delta = true;
    s->eta = 1.0f;
    if (u_lobe < r) {
        s->wi = rc_reflect_local(wo);
        s->f = tint * (r / fabs(wo.z));
        s->pdf = r;
    } else {
        s->wi = -wo;
        s->f = tint * ((1.0f - r) / fabs(wo.z));
        s->pdf = 1.0f - r;
    }
    return s->pdf > 0.0f;
}
