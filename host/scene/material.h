// Surface materials (docs/scene-format.md): diffuse (Lambert), phong (energy-conserving modified
// Phong), ward (anisotropic Ward with bounded albedo), conductor (smooth or Trowbridge-Reitz
// rough, complex index per channel), dielectric (smooth or rough glass, water) and
// thindielectric (a window pane) and diffusetransmission (a lampshade), and their device form.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "shared/types.h"

namespace rc {

enum class MaterialKind {
    kDiffuse,
    kPhong,
    kWard,
    kConductor,
    kDielectric,
    kThinDielectric,
    kDiffuseTransmission
};

struct Material {
    std::string name;
    MaterialKind kind = MaterialKind::kDiffuse;
    glm::vec3 diffuse{0.5f};   // diffuse reflectance; scales the texture when there is one
    int diffuse_texture = -1;  // index into Scene::textures, or -1
    glm::vec3 specular{0.0f};  // conductor, dielectrics: a tint (1: none)
    float exponent = 0.0f;     // phong
    float alpha_x = 0.1f;      // ward; conductor, dielectric: Trowbridge-Reitz alpha (0: smooth)
    float alpha_y = 0.1f;
    glm::vec3 eta{1.0f};             // conductor: the index's real part per channel
    glm::vec3 k{0.0f};               // conductor: its imaginary part
    float ior = 1.5f;                // dielectrics: the index inside over outside
    glm::vec3 transmittance{0.25f};  // diffuse transmission (its reflectance is `specular`)
    // Diffuse transmission: diffuse_texture scales its reflectance, its transmittance or both
    // (RC_TEXTURE_SCALES_* bits); 0 for every other model.
    int texture_targets = 0;
};

// Whether the material transmits light (the dielectrics, the diffuse transmitter).
bool transmits(const Material& material);

// Whether its only lobes are the Lambertian and a Phong or Ward lobe (what every caching method
// serves); the conductor and the dielectrics are path traced.
bool is_reflectance_model(const Material& material);

// The conductor that pbrt-v4 makes of a normal-incidence reflectance r per channel: eta = 1,
// k = 2 sqrt(r) / sqrt(1 - r) (pbrt-v4's ConductorMaterial), r clamped below 1.
void set_conductor_reflectance(Material& material, glm::vec3 r);

// The device form; the diffuse lobe is sampled with probability lum(diffuse) / lum(diffuse +
// specular).
shared::Material to_device(const Material& material);

const char* material_kind_name(MaterialKind kind);

// The Phong exponent of a microfacet roughness alpha: n = 2 / alpha^2 - 2 (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces", §5.2), within [0, 1e6] (1e6 for
// alpha <= 1e-3: a near mirror).
float phong_exponent_of_alpha(float alpha);

}  // namespace rc
