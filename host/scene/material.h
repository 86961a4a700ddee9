// Surface materials (docs/scene-format.md): diffuse (Lambert), phong (energy-conserving modified
// Phong) and ward (anisotropic Ward with bounded albedo), and their device form.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "shared/types.h"

namespace rc {

enum class MaterialKind { kDiffuse, kPhong, kWard };

struct Material {
    std::string name;
    MaterialKind kind = MaterialKind::kDiffuse;
    glm::vec3 diffuse{0.5f};   // diffuse reflectance; scales the texture when there is one
    int diffuse_texture = -1;  // index into Scene::textures, or -1
    glm::vec3 specular{0.0f};
    float exponent = 0.0f;  // phong
    float alpha_x = 0.1f;   // ward
    float alpha_y = 0.1f;
};

// The device form; the diffuse lobe is sampled with probability lum(diffuse) / lum(diffuse +
// specular).
shared::Material to_device(const Material& material);

const char* material_kind_name(MaterialKind kind);

// The Phong exponent of a microfacet roughness alpha: n = 2 / alpha^2 - 2 (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces", §5.2), within [0, 1e6] (1e6 for
// alpha <= 1e-3: a near mirror).
float phong_exponent_of_alpha(float alpha);

}  // namespace rc
