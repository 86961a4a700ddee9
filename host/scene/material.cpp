#include "scene/material.h"

#include <algorithm>
#include <cmath>

#include "util/glm_helpers.h"

namespace rc {

const char* material_kind_name(MaterialKind kind) {
    switch (kind) {
        case MaterialKind::kDiffuse:
            return "diffuse";
        case MaterialKind::kPhong:
            return "phong";
        case MaterialKind::kWard:
            return "ward";
        case MaterialKind::kConductor:
            return "conductor";
        case MaterialKind::kDielectric:
            return "dielectric";
        case MaterialKind::kThinDielectric:
            return "thindielectric";
        case MaterialKind::kDiffuseTransmission:
            return "diffusetransmission";
    }
    return "?";
}

bool transmits(const Material& material) {
    return material.kind == MaterialKind::kDielectric ||
           material.kind == MaterialKind::kThinDielectric ||
           material.kind == MaterialKind::kDiffuseTransmission;
}

bool is_reflectance_model(const Material& material) {
    return material.kind == MaterialKind::kDiffuse || material.kind == MaterialKind::kPhong ||
           material.kind == MaterialKind::kWard;
}

void set_conductor_reflectance(Material& material, glm::vec3 r) {
    material.eta = glm::vec3(1.0f);
    for (int c = 0; c < 3; ++c) {
        const float clamped = std::clamp(r[c], 0.0f, 0.9999f);
        material.k[c] = 2.0f * std::sqrt(clamped) / std::sqrt(1.0f - clamped);
    }
}

namespace {

// The device form of a conductor, dielectric or diffuse transmitter: one lobe, no (reflective)
// diffuse one.
shared::Material single_lobe_device(const Material& material) {
    shared::Material m{};
    m.specular = {material.specular.r, material.specular.g, material.specular.b, 0.0f};
    m.alpha_x = material.alpha_x;
    m.alpha_y = material.alpha_y;
    m.diffuse_probability = 0.0f;
    m.texture = -1;
    if (material.kind == MaterialKind::kDiffuseTransmission) {
        m.model = RC_MATERIAL_DIFFUSE_TRANSMISSION;
        if (material.texture_targets != 0) {
            m.texture = material.diffuse_texture;
            m.texture_targets = material.texture_targets;
        }
        const glm::vec3& t = material.transmittance;
        m.k = {t.r, t.g, t.b, 0.0f};
    } else if (material.kind == MaterialKind::kConductor) {
        m.model = RC_MATERIAL_CONDUCTOR;
        m.eta = {material.eta.r, material.eta.g, material.eta.b, 0.0f};
        m.k = {material.k.r, material.k.g, material.k.b, 0.0f};
    } else {
        m.model = material.kind == MaterialKind::kDielectric ? RC_MATERIAL_DIELECTRIC
                                                             : RC_MATERIAL_THIN_DIELECTRIC;
        m.eta = {material.ior, material.ior, material.ior, 0.0f};
    }
    return m;
}

}  // namespace

shared::Material to_device(const Material& material) {
    if (!is_reflectance_model(material)) {
        return single_lobe_device(material);
    }
    shared::Material m{};
    m.diffuse = {material.diffuse.r, material.diffuse.g, material.diffuse.b, 0.0f};
    const bool specular = material.kind != MaterialKind::kDiffuse;
    const glm::vec3 ks = specular ? material.specular : glm::vec3(0.0f);
    m.specular = {ks.r, ks.g, ks.b, 0.0f};
    m.exponent = material.exponent;
    const float kd_weight = luminance(material.diffuse);
    const float ks_weight = luminance(ks);
    float diffuse_probability = 1.0f;
    if (specular && ks_weight > 0.0f) {
        diffuse_probability = kd_weight / (kd_weight + ks_weight);
    }
    m.alpha_x = material.alpha_x;
    m.alpha_y = material.alpha_y;
    m.diffuse_probability = diffuse_probability;
    m.model = material.kind == MaterialKind::kDiffuse ? RC_MATERIAL_DIFFUSE
              : material.kind == MaterialKind::kPhong ? RC_MATERIAL_PHONG
                                                      : RC_MATERIAL_WARD;
    m.texture = material.diffuse_texture;
    return m;
}

float phong_exponent_of_alpha(float alpha) {
    if (!(alpha > 1e-3f)) {
        return 1e6f;
    }
    return std::clamp(2.0f / (alpha * alpha) - 2.0f, 0.0f, 1e6f);
}

}  // namespace rc
