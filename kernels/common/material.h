// Reflection models: evaluation, importance sampling and pdf of every material, in the local
// shading frame (z = shading normal, on the side the incoming ray arrives from). The diffuse,
// phong and ward models reflect only: a Lambertian lobe with an optional Phong or Ward specular
// lobe, the diffuse lobe sampled with probability Material.diffuse_probability, so their pdfs are
// the mixture of both lobes'. The conductor and the dielectrics are single lobes of their own
// files (conductor_bsdf.h, dielectric_bsdf.h, thin_dielectric_bsdf.h, diffuse_transmission_bsdf.h),
// smooth ones delta lobes.
#pragma once

#include "common/bsdf_sample.h"
#include "common/conductor_bsdf.h"
#include "common/dielectric_bsdf.h"
#include "common/diffuse_transmission_bsdf.h"
#include "common/math.h"
#include "common/phong_brdf.h"
#include "common/sampling.h"
#include "common/thin_dielectric_bsdf.h"
#include "common/ward_brdf.h"
#include "shared/types.h"

// A material at one surface point, textures resolved.
typedef struct SurfaceMaterial {
    int kind;
    float3 diffuse;
    float3 specular;  // phong, ward: the lobe's reflectance; conductor, dielectrics: a tint;
                      // diffuse transmission: its reflectance
    float exponent;
    float alpha_x;  // ward: its roughness; conductor, dielectric: the Trowbridge-Reitz alpha
    float alpha_y;
    float diffuse_probability;
    float3 eta;  // conductor: eta per channel; dielectrics: x, the far side's index over wo's
    float3 k;    // conductor: k per channel; diffuse transmission: its transmittance
} SurfaceMaterial;

// The material's constant parameters (scene_data.h applies textures and the side on top).
RC_FUNC SurfaceMaterial rc_surface_material_of(const Material* material) {
    SurfaceMaterial m;
    m.kind = material->model;
    m.diffuse = material->diffuse.xyz;
    m.specular = material->specular.xyz;
    m.exponent = material->exponent;
    m.alpha_x = material->alpha_x;
    m.alpha_y = material->alpha_y;
    m.diffuse_probability = material->diffuse_probability;
    m.eta = material->eta.xyz;
    m.k = material->k.xyz;
    return m;
}

RC_FUNC TrowbridgeReitz rc_material_distribution(const SurfaceMaterial* m) {
    TrowbridgeReitz d;
    d.alpha_x = m->alpha_x;
    d.alpha_y = m->alpha_y;
    return d;
}

// Whether the material lets light through (wi below the surface).
RC_FUNC bool rc_material_transmits(const SurfaceMaterial* m) {
    return m->kind == RC_MATERIAL_DIELECTRIC || m->kind == RC_MATERIAL_THIN_DIELECTRIC ||
           m->kind == RC_MATERIAL_DIFFUSE_TRANSMISSION;
}

// Whether every lobe of the material is a delta lobe (rc_material_eval is 0 everywhere: light
// sampling cannot contribute).
RC_FUNC bool rc_material_is_delta(const SurfaceMaterial* m) {
    if (m->kind == RC_MATERIAL_THIN_DIELECTRIC) {
        return true;
    }
    if (m->kind == RC_MATERIAL_DIELECTRIC) {
        return rc_dielectric_smooth(rc_material_distribution(m), m->eta.x);
    }
    if (m->kind == RC_MATERIAL_CONDUCTOR) {
        return rc_tr_effectively_smooth(rc_material_distribution(m));
    }
    return false;
}

// Whether the material has the Phong or Ward lobe the glossy caches represent.
RC_FUNC bool rc_material_has_glossy_lobe(const SurfaceMaterial* m) {
    return (m->kind == RC_MATERIAL_PHONG || m->kind == RC_MATERIAL_WARD) &&
           !rc_is_black(m->specular);
}

// F(w_i) = f_s(w_o, w_i) cos(theta_i) of a material's specular lobe with unit specular
// reflectance (the Phong or Ward lobe times the cosine): zero below the horizon and for materials
// without a specular lobe. The lobe both glossy caches represent (radiance caching's BRDF tables,
// SDRC's importance sampling).
RC_FUNC float rc_specular_lobe(const Material* material, float3 wo, float3 wi) {
    if (wi.z <= 0.0f) {
        return 0.0f;
    }
    if (material->model == RC_MATERIAL_PHONG) {
        return rc_phong_specular(material->exponent, wo, wi) * wi.z;
    }
    if (material->model == RC_MATERIAL_WARD) {
        return rc_ward_specular(material->alpha_x, material->alpha_y, wo, wi) * wi.z;
    }
    return 0.0f;
}

// The BSDF value f(wo, wi) (without the cosine).
RC_FUNC float3 rc_material_eval(const SurfaceMaterial* m, float3 wo, float3 wi) {
    if (m->kind == RC_MATERIAL_CONDUCTOR) {
        return m->specular * rc_conductor_eval(rc_material_distribution(m), m->eta, m->k, wo, wi);
    }
    if (m->kind == RC_MATERIAL_DIELECTRIC) {
        return m->specular * rc_dielectric_eval(rc_material_distribution(m), m->eta.x, wo, wi);
    }
    if (m->kind == RC_MATERIAL_DIFFUSE_TRANSMISSION) {
        return rc_diffuse_transmission_eval(m->specular, m->k, wo, wi);
    }
    if (m->kind == RC_MATERIAL_THIN_DIELECTRIC || wo.z <= 0.0f || wi.z <= 0.0f) {
        return (float3)(0.0f);
    }
    float3 f = m->diffuse * RC_INV_PI;
    if (m->kind == RC_MATERIAL_PHONG) {
        f += m->specular * rc_phong_specular(m->exponent, wo, wi);
    } else if (m->kind == RC_MATERIAL_WARD) {
        f += m->specular * rc_ward_specular(m->alpha_x, m->alpha_y, wo, wi);
    }
    return f;
}

// The solid-angle density with which rc_material_sample returns wi (0 for delta lobes).
RC_FUNC float rc_material_pdf(const SurfaceMaterial* m, float3 wo, float3 wi) {
    if (m->kind == RC_MATERIAL_CONDUCTOR) {
        return rc_conductor_pdf(rc_material_distribution(m), wo, wi);
    }
    if (m->kind == RC_MATERIAL_DIELECTRIC) {
        return rc_dielectric_pdf(rc_material_distribution(m), m->eta.x, wo, wi);
    }
    if (m->kind == RC_MATERIAL_DIFFUSE_TRANSMISSION) {
        return rc_diffuse_transmission_pdf(m->specular, m->k, wo, wi);
    }
    if (m->kind == RC_MATERIAL_THIN_DIELECTRIC || wo.z <= 0.0f || wi.z <= 0.0f) {
        return 0.0f;
    }
    const float diffuse_pdf = wi.z * RC_INV_PI;
    float specular_pdf = 0.0f;
    if (m->kind == RC_MATERIAL_PHONG) {
        specular_pdf = rc_phong_pdf(m->exponent, wo, wi);
    } else if (m->kind == RC_MATERIAL_WARD) {
        specular_pdf = rc_ward_pdf(m->alpha_x, m->alpha_y, wo, wi);
    }
    return m->diffuse_probability * diffuse_pdf + (1.0f - m->diffuse_probability) * specular_pdf;
}

// The diffuse, phong and ward models' sampling: a lobe by u_lobe, wi from (u1, u2).
RC_FUNC bool rc_reflection_sample(const SurfaceMaterial* m, float3 wo, float u_lobe, float u1,
                                  float u2, BsdfSample* s) {
    if (wo.z <= 0.0f) {
        return false;
    }
    if (u_lobe < m->diffuse_probability) {
        s->wi = rc_cosine_hemisphere(u1, u2);
    } else if (m->kind == RC_MATERIAL_PHONG) {
        s->wi = rc_phong_sample(m->exponent, wo, u1, u2);
    } else if (m->kind == RC_MATERIAL_WARD) {
        s->wi = rc_ward_sample(m->alpha_x, m->alpha_y, wo, u1, u2);
    } else {
        return false;
    }
    if (s->wi.z <= 0.0f) {
        return false;
    }
    s->pdf = rc_material_pdf(m, wo, s->wi);
    s->f = rc_material_eval(m, wo, s->wi);
    s->eta = 1.0f;
    s->delta = false;
    return s->pdf > 0.0f;
}

// Samples wi for wo from (u_lobe, u1, u2) in [0,1)^3 into *s. False where sampling fails (wo
// below a reflective surface, a direction below it, total internal reflection of a rough
// interface's sampled normal).
RC_FUNC bool rc_material_sample(const SurfaceMaterial* m, float3 wo, float u_lobe, float u1,
                                float u2, BsdfSample* s) {
    bool sampled;
    if (m->kind == RC_MATERIAL_CONDUCTOR) {
        sampled = rc_conductor_sample(rc_material_distribution(m), m->eta, m->k, wo, u1, u2, s);
    } else if (m->kind == RC_MATERIAL_DIELECTRIC) {
        return rc_dielectric_sample(rc_material_distribution(m), m->eta.x, m->specular, wo, u_lobe,
                                    u1, u2, s);
    } else if (m->kind == RC_MATERIAL_THIN_DIELECTRIC) {
        return rc_thin_dielectric_sample(m->eta.x, m->specular, wo, u_lobe, s);
    } else if (m->kind == RC_MATERIAL_DIFFUSE_TRANSMISSION) {
        return rc_diffuse_transmission_sample(m->specular, m->k, wo, u_lobe, u1, u2, s);
    } else {
        return rc_reflection_sample(m, wo, u_lobe, u1, u2, s);
    }
    s->f *= m->specular;
    return sampled;
}
