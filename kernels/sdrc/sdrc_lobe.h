// BRDF importance sampling of a material's specular lobe for SDRC (SDRC §4.3-4.5; DESIGN.md
// §6.5): the directions records and interpolation draw, and each one's weight in the outgoing
// estimate (eq. 3) with unit specular reflectance, f_s cos(theta_i) / (rho_s p).
#pragma once

#include "common/material.h"
#include "shared/rng.h"

// The specular lobe of `material` at w_o (shading frame) sampled from (u1, u2): the direction
// into *wi, its density into *pdf, and f_s cos(theta_i) / (rho_s p) into *weight. False when the
// material has no specular lobe or the sample leaves below the surface (a direction whose light
// the lobe's estimate counts as zero).
RC_FUNC bool rc_sdrc_lobe_sample(const Material* material, float3 wo, float u1, float u2,
                                 float3* wi, float* pdf, float* weight) {
    if (wo.z <= 0.0f) {
        return false;
    }
    if (material->model == RC_MATERIAL_PHONG) {
        *wi = rc_phong_sample(material->exponent, wo, u1, u2);
        if (wi->z <= 0.0f) {
            return false;
        }
        *pdf = rc_phong_pdf(material->exponent, wo, *wi);
        *weight = rc_phong_specular(material->exponent, wo, *wi) * wi->z / *pdf;
    } else if (material->model == RC_MATERIAL_WARD) {
        *wi = rc_ward_sample(material->alpha_x, material->alpha_y, wo, u1, u2);
        if (wi->z <= 0.0f) {
            return false;
        }
        *pdf = rc_ward_pdf(material->alpha_x, material->alpha_y, wo, *wi);
        *weight = rc_ward_specular(material->alpha_x, material->alpha_y, wo, *wi) * wi->z / *pdf;
    } else {
        return false;
    }
    return *pdf > 0.0f && isfinite(*weight);
}

// f_s(w_o, w_i) cos(theta_i) / rho_s of the material's specular lobe (zero below the surface).
RC_FUNC float rc_sdrc_lobe_value(const Material* material, float3 wo, float3 wi) {
    return wo.z <= 0.0f ? 0.0f : rc_specular_lobe(material, wo, wi);
}

// The uniform numbers of direction `index` of stream `stream` under `key` (words 0 and 1).
RC_FUNC void rc_sdrc_direction_numbers(uint key_lo, uint key_hi, uint stream, uint index, float* u1,
                                       float* u2) {
    RngStream rng = rc_rng_stream(key_lo, key_hi, stream, index);
    *u1 = rc_rng_next_float(&rng);
    *u2 = rc_rng_next_float(&rng);
}
