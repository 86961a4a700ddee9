// The specular lobe of the modified Phong model (Lafortune and Willems 1994).
#pragma once

#include "common/math.h"
#include "common/sampling.h"

// Modified Phong, specular lobe (Lafortune and Willems, "Using the Modified Phong Reflectance
// Model for Physically Based Rendering", 1994): ks (n + 2) / (2 pi) cos^n(alpha), alpha the angle
// between wi and the mirror direction of wo. Energy conserving for kd + ks <= 1.
RC_FUNC float rc_phong_lobe_cosine(float3 wo, float3 wi) {
    return dot((float3)(-wo.x, -wo.y, wo.z), wi);
}

RC_FUNC float rc_phong_specular(float exponent, float3 wo, float3 wi) {
    const float c = rc_phong_lobe_cosine(wo, wi);
    return c > 0.0f ? (exponent + 2.0f) * RC_INV_TWO_PI * pow(c, exponent) : 0.0f;
}

// pdf of the lobe sampling: (n + 1) / (2 pi) cos^n(alpha) around the mirror direction.
RC_FUNC float rc_phong_pdf(float exponent, float3 wo, float3 wi) {
    const float c = rc_phong_lobe_cosine(wo, wi);
    return c > 0.0f ? (exponent + 1.0f) * RC_INV_TWO_PI * pow(c, exponent) : 0.0f;
}

RC_FUNC float3 rc_phong_sample(float exponent, float3 wo, float u1, float u2) {
    const float cos_alpha = pow(1.0f - u1, 1.0f / (exponent + 1.0f));
    const float sin_alpha = sqrt(fmax(0.0f, 1.0f - cos_alpha * cos_alpha));
    const float phi = 2.0f * RC_PI * u2;
    const float3 mirror = (float3)(-wo.x, -wo.y, wo.z);
    return rc_to_world((float3)(sin_alpha * cos(phi), sin_alpha * sin(phi), cos_alpha), mirror);
}
