// glTF 2.0 metallic-roughness materials mapped to radcache's (docs/importing.md#gltf-20-import):
// base colour to the diffuse lobe, metallic and roughness to a Phong lobe, the base-colour texture
// to the diffuse texture, the emissive factor (times KHR_materials_emissive_strength) to an area
// light's radiance.
#pragma once

#include <tiny_gltf.h>

#include <filesystem>
#include <glm/vec3.hpp>
#include <map>
#include <set>
#include <string>

#include "scene/scene.h"

namespace rc {

// One warning per unsupported feature of a glTF file ("<file>: glTF <feature> not supported:
// <what>").
class GltfWarnings {
   public:
    explicit GltfWarnings(std::string file) : file_(std::move(file)) {}
    void warn(const std::string& feature, const std::string& what);

   private:
    std::string file_;
    std::set<std::string> warned_;
};

struct GltfMaterial {
    int index = -1;            // into Scene::materials
    glm::vec3 emission{0.0f};  // area-light radiance; 0: not emitting
    int tex_coord = 0;         // the base-colour texture's TEXCOORD set
};

// The roughness below which a dielectric keeps its specular lobe (docs: the mapping).
inline constexpr float kGltfGlossyRoughness = 0.5f;

// The Phong exponent of a glTF roughness: alpha = roughness^2 and the Beckmann-Phong
// correspondence n = 2 / alpha^2 - 2 (Walter et al. 2007, "Microfacet Models for Refraction
// through Rough Surfaces", §5.2), within [0, 1e6].
float gltf_phong_exponent(float roughness);

// The scene materials of a model's materials, made on first use.
class GltfMaterials {
   public:
    GltfMaterials(const std::filesystem::path& path, const tinygltf::Model& model, Scene& scene,
                  GltfWarnings& warnings)
        : path_(path), model_(model), scene_(scene), warnings_(warnings) {}

    // Material `index` (-1: glTF's default material); `where` names the primitive in errors.
    const GltfMaterial& get(int index, const std::string& where);

   private:
    GltfMaterial make(int index, const std::string& where);
    int texture(int index, const std::string& where);
    void transmissive(const tinygltf::Material& gltf, const std::string& what, float roughness,
                      Material* material);

    std::filesystem::path path_;
    const tinygltf::Model& model_;
    Scene& scene_;
    GltfWarnings& warnings_;
    std::map<int, GltfMaterial> made_;
    std::map<int, int> textures_;  // glTF image -> Scene::textures
};

}  // namespace rc
