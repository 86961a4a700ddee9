// A diffuse transmitter (a lampshade, a curtain, leaves): Lambertian reflection R / pi on the side
// light arrives from and Lambertian transmission T / pi through the surface, R + T <= 1 per
// channel (pbrt-v4's DiffuseTransmissionBxDF). Sampled by cosine, reflection chosen with
// probability max(R) / (max(R) + max(T)). Transmission here does not refract: radiance is not
// scaled.
#pragma once

#include "common/bsdf_sample.h"
#include "common/math.h"
#include "common/sampling.h"

RC_FUNC float rc_diffuse_transmission_reflect_probability(float3 r, float3 t) {
    const float pr = rc_max_component(r);
    const float pt = rc_max_component(t);
    return pr + pt > 0.0f ? pr / (pr + pt) : 0.0f;
}

RC_FUNC float3 rc_diffuse_transmission_eval(float3 r, float3 t, float3 wo, float3 wi) {
    if (wo.z == 0.0f || wi.z == 0.0f) {
        return (float3)(0.0f);
    }
    return (wo.z * wi.z > 0.0f ? r : t) * RC_INV_PI;
}

RC_FUNC float rc_diffuse_transmission_pdf(float3 r, float3 t, float3 wo, float3 wi) {
    if (wo.z == 0.0f || wi.z == 0.0f || rc_is_black(r + t)) {
        return 0.0f;
    }
    const float p = rc_diffuse_transmission_reflect_probability(r, t);
    return (wo.z * wi.z > 0.0f ? p : 1.0f - p) * fabs(wi.z) * RC_INV_PI;
}

RC_FUNC bool rc_diffuse_transmission_sample(float3 r, float3 t, float3 wo, float u_lobe, float u1,
                                            float u2, BsdfSample* s) {
    if (wo.z == 0.0f || rc_is_black(r + t)) {
        return false;
    }
    s->wi = rc_cosine_hemisphere(u1, u2);
    const bool reflect = u_lobe < rc_diffuse_transmission_reflect_probability(r, t);
    if (reflect != (wo.z > 0.0f)) {
        s->wi.z = -s->wi.z;
    }
    s->pdf = rc_diffuse_transmission_pdf(r, t, wo, s->wi);
    s->f = rc_diffuse_transmission_eval(r, t, wo, s->wi);
    s->eta = 1.0f;
    s->delta = false;
    return s->pdf > 0.0f;
}
