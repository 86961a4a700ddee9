// pbrt-v4 materials and textures mapped to radcache's (docs/importing.md#pbrt-v4-import):
// "diffuse" as is; "coateddiffuse" as a Phong lobe of the coat's Fresnel reflectance at normal
// incidence over the diffuse base; "conductor" as a Phong lobe of the metal's reflectance at
// normal incidence; roughness to the Phong exponent through the Beckmann-Phong correspondence.
// Spectrum "imagemap" and "constant" textures serve as reflectances. A material is made when a
// shape first uses it, so a refused one that no shape uses costs nothing; one a shape uses is
// an Error naming where it was defined.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "scene/pbrt_parser.h"
#include "scene/scene.h"

namespace rc {

class PbrtMaterials {
   public:
    PbrtMaterials(Scene& scene, const SceneFiles& files, std::filesystem::path dir)
        : scene_(scene), files_(files), dir_(std::move(dir)) {}

    // Texture "name" "spectrum"|"float" "class" ...
    void define_texture(const PbrtDirective& directive);
    // Material "type" ...: returns the handle of a new material.
    int define(const PbrtDirective& directive);
    // MakeNamedMaterial "name" "string type" ...
    void define_named(const PbrtDirective& directive);
    // NamedMaterial "name": its handle; Error when no material of that name is defined.
    int named(const PbrtDirective& directive) const;
    // The scene material of a handle (-1: pbrt's default, diffuse 0.5), made on first use.
    int scene_material(int handle);

   private:
    struct Spec {
        PbrtDirective directive;
        std::string type;
        std::string what;  // "file:line: Material \"type\""
        int made = -1;     // index into Scene::materials
    };
    struct TextureEntry {
        std::string what;       // "file:line: Texture \"name\""
        std::string refused;    // why it cannot serve as a reflectance; empty: it can
        int texture = -1;       // imagemap: index into Scene::textures
        glm::vec3 value{1.0f};  // the scale (imagemap) or the colour (constant)
    };

    Material make(Spec& spec);
    void make_dielectric(class PbrtParams& params, bool thin, Material* material);
    void make_conductor(class PbrtParams& params, Material* material);
    void make_diffuse_transmission(class PbrtParams& params, Material* material);
    glm::vec3 reflectance(class PbrtParams& params, const std::string& name, glm::vec3 fallback,
                          int* texture);
    int load_image(const std::filesystem::path& path, class PbrtParams& params);
    int bake_checkerboard(class PbrtParams& params, const std::string& what);
    void scale_texture(class PbrtParams& params, TextureEntry& entry);

    Scene& scene_;
    const SceneFiles& files_;
    std::filesystem::path dir_;
    std::vector<Spec> specs_;
    std::map<std::string, int> named_;
    std::map<std::string, TextureEntry> textures_;
    std::map<std::string, int> images_;  // path -> Scene::textures
};

}  // namespace rc
