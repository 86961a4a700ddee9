#include "scene/material.h"

#include <algorithm>

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
    }
    return "?";
}

shared::Material to_device(const Material& material) {
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
