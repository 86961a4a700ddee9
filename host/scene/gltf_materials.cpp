#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"
#include "util/log.h"
#include "util/text.h"

namespace rc {

void GltfWarnings::warn(const std::string& feature, const std::string& what) {
    if (warned_.insert(feature).second) {
        log_warning(file_ + ": glTF " + feature + " not supported: " + what);
    }
}

float gltf_phong_exponent(float roughness) {
    return phong_exponent_of_alpha(roughness * roughness);
}

const GltfMaterial& GltfMaterials::get(int index, const std::string& where) {
    const auto found = made_.find(index);
    if (found != made_.end()) {
        return found->second;
    }
    return made_[index] = make(index, where);
}

namespace {

// A factor of `count` numbers, each in [0, 1].
glm::vec3 unit_colour(const std::vector<double>& factor, size_t count, glm::vec3 fallback,
                      const std::string& what) {
    if (factor.empty()) {
        return fallback;
    }
    if (factor.size() != count) {
        throw Error(what + ": expected " + std::to_string(count) + " numbers");
    }
    for (size_t c = 0; c < 3; ++c) {
        if (!(factor[c] >= 0.0 && factor[c] <= 1.0)) {
            throw Error(what + ": component " + std::to_string(c) + " outside [0, 1]");
        }
    }
    return glm::vec3(factor[0], factor[1], factor[2]);
}

// The bytes of buffer view `index` (an image stored in a .gltf's buffer: tinygltf reads those of
// .glb files only).
std::string buffer_view_bytes(const tinygltf::Model& model, int index, const std::string& what) {
    if (static_cast<size_t>(index) >= model.bufferViews.size()) {
        throw Error(what + ": buffer view " + std::to_string(index) + " does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[index];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
        throw Error(what + ": buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
        throw Error(what + ": buffer view " + std::to_string(index) + " runs past its buffer");
    }
    return std::string(
        data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset),
        data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset + view.byteLength));
}

float unit_number(double value, const std::string& what) {
    if (!(value >= 0.0 && value <= 1.0)) {
        throw Error(what + " = " + std::to_string(value) + " outside [0, 1]");
    }
    return static_cast<float>(value);
}

}  // namespace

GltfMaterial GltfMaterials::make(int index, const std::string& where) {
    if (index >= 0 && static_cast<size_t>(index) >= model_.materials.size()) {
        throw Error(where + ": material " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Material gltf = index >= 0 ? model_.materials[index] : tinygltf::Material();
    const std::string what = path_.string() + ": material " + std::to_string(index);
    const tinygltf::PbrMetallicRoughness& pbr = gltf.pbrMetallicRoughness;
    const glm::vec3 base =
        unit_colour(pbr.baseColorFactor, 4, glm::vec3(1.0f), what + ": baseColorFactor");
    const float metallic = unit_number(pbr.metallicFactor, what + ": metallicFactor");
    const float roughness = unit_number(pbr.roughnessFactor, what + ": roughnessFactor");
    Material material;
    material.name = "gltf" + std::to_string(index) + (gltf.name.empty() ? "" : "_" + gltf.name);
    if (metallic == 1.0f && pbr.baseColorTexture.index < 0 &&
        pbr.metallicRoughnessTexture.index < 0) {
        // A plain metal: the Trowbridge-Reitz conductor of reflectance base, alpha roughness^2
        // (glTF 2.0, Appendix B: the metal BRDF is F0 = baseColor with alpha = roughness^2).
        material.kind = MaterialKind::kConductor;
        material.diffuse = glm::vec3(0.0f);
        material.specular = glm::vec3(1.0f);
        set_conductor_reflectance(material, base);
        material.alpha_x = material.alpha_y = roughness * roughness;
    } else if (metallic > 0.0f || roughness < kGltfGlossyRoughness) {
        // Fresnel at normal incidence: 0.04 for the dielectric, the base colour for the metal.
        material.kind = MaterialKind::kPhong;
        material.specular = metallic * base + (1.0f - metallic) * glm::vec3(0.04f);
        material.diffuse = (1.0f - metallic) * 0.96f * base;
        material.exponent = gltf_phong_exponent(roughness);
    } else {
        material.diffuse = base;
    }
    GltfMaterial result;
    if (pbr.baseColorTexture.index >= 0) {
        material.diffuse_texture = texture(pbr.baseColorTexture.index, what);
        result.tex_coord = pbr.baseColorTexture.texCoord;
        if (metallic > 0.0f) {
            warnings_.warn("base colour texture on metals",
                           "the texture tints the diffuse lobe only, baseColorFactor the specular");
        }
        if (pbr.baseColorTexture.extensions.count("KHR_texture_transform")) {
            warnings_.warn("KHR_texture_transform", "ignored");
        }
    }
    if (pbr.metallicRoughnessTexture.index >= 0) {
        warnings_.warn("metallicRoughnessTexture", "the factors apply over the whole surface");
    }
    if (gltf.normalTexture.index >= 0) {
        warnings_.warn("normalTexture", "ignored: the mesh's normals shade");
    }
    if (gltf.occlusionTexture.index >= 0) {
        warnings_.warn("occlusionTexture", "ignored (light transport computes occlusion)");
    }
    if (gltf.emissiveTexture.index >= 0) {
        warnings_.warn("emissiveTexture", "emissiveFactor applies over the whole surface");
    }
    if (gltf.alphaMode != "OPAQUE") {
        warnings_.warn("alphaMode " + excerpt(gltf.alphaMode), "surfaces are opaque");
    }
    float strength = 1.0f;
    for (const auto& [name, value] : gltf.extensions) {
        if (name == "KHR_materials_transmission" || name == "KHR_materials_ior" ||
            name == "KHR_materials_volume") {
            continue;  // transmissive(): read together
        }
        if (name == "KHR_materials_emissive_strength") {
            const tinygltf::Value& s = value.Get("emissiveStrength");
            if (!s.IsNumber() || !(s.GetNumberAsDouble() >= 0.0) ||
                !(s.GetNumberAsDouble() <= 1e9)) {
                throw Error(what + ": emissiveStrength must be a number in [0, 1e9]");
            }
            strength = static_cast<float>(s.GetNumberAsDouble());
        } else {
            warnings_.warn("material extension " + excerpt(name), "ignored");
        }
    }
    transmissive(gltf, what, roughness, &material);
    result.emission =
        unit_colour(gltf.emissiveFactor, 3, glm::vec3(0.0f), what + ": emissiveFactor") * strength;
    scene_.materials.push_back(material);
    result.index = static_cast<int>(scene_.materials.size() - 1);
    return result;
}

// KHR_materials_transmission with transmissionFactor >= 0.5 (and KHR_materials_ior's ior,
// default 1.5): glass. Thin-walled without KHR_materials_volume, as the extension defines it (a
// `thindielectric`), a solid `dielectric` of alpha roughness^2 with it. A transmission below 0.5
// is left opaque, and a transmission texture or volume attenuation ignored: both warned.
void GltfMaterials::transmissive(const tinygltf::Material& gltf, const std::string& what,
                                 float roughness, Material* material) {
    const auto found = gltf.extensions.find("KHR_materials_transmission");
    if (found == gltf.extensions.end()) {
        return;
    }
    const tinygltf::Value& factor = found->second.Get("transmissionFactor");
    const float transmission =
        factor.IsNumber() ? unit_number(factor.GetNumberAsDouble(), what + ": transmissionFactor")
                          : 0.0f;
    if (found->second.Has("transmissionTexture")) {
        warnings_.warn("transmissionTexture", "transmissionFactor applies over the whole surface");
    }
    if (transmission < 0.5f) {
        if (transmission > 0.0f) {
            warnings_.warn("transmissionFactor below 0.5", "the surface is opaque");
        }
        return;
    }
    float ior = 1.5f;
    const auto ior_extension = gltf.extensions.find("KHR_materials_ior");
    if (ior_extension != gltf.extensions.end() && ior_extension->second.Has("ior")) {
        const tinygltf::Value& value = ior_extension->second.Get("ior");
        ior = value.IsNumber() ? static_cast<float>(value.GetNumberAsDouble()) : -1.0f;
        if (!(ior >= 1.0f && ior <= 10.0f)) {
            throw Error(what + ": KHR_materials_ior ior must be a number in [1, 10]");
        }
    }
    const bool solid = gltf.extensions.count("KHR_materials_volume") != 0;
    if (solid && gltf.extensions.at("KHR_materials_volume").Has("attenuationColor")) {
        warnings_.warn("volume attenuation", "glass is clear");
    }
    material->kind = solid ? MaterialKind::kDielectric : MaterialKind::kThinDielectric;
    material->diffuse = glm::vec3(0.0f);
    material->diffuse_texture = -1;
    material->specular = glm::vec3(1.0f);
    material->ior = ior;
    material->alpha_x = material->alpha_y = solid ? roughness * roughness : 0.0f;
}

int GltfMaterials::texture(int index, const std::string& what) {
    if (index < 0 || static_cast<size_t>(index) >= model_.textures.size()) {
        throw Error(what + ": texture " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Texture& texture = model_.textures[index];
    if (texture.source < 0 || static_cast<size_t>(texture.source) >= model_.images.size()) {
        throw Error(what + ": texture " + std::to_string(index) + " has no image");
    }
    if (texture.sampler >= 0 && static_cast<size_t>(texture.sampler) < model_.samplers.size()) {
        const tinygltf::Sampler& sampler = model_.samplers[texture.sampler];
        if (sampler.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT ||
            sampler.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT) {
            warnings_.warn("texture wrap modes other than REPEAT", "textures repeat");
        }
    }
    const auto found = textures_.find(texture.source);
    if (found != textures_.end()) {
        return found->second;
    }
    const tinygltf::Image& image = model_.images[texture.source];
    std::string name = image.uri;
    if (name.empty() || name.rfind("data:", 0) == 0) {
        const std::string extension = image.mimeType == "image/jpeg" ? ".jpg" : ".png";
        name = "image" + std::to_string(texture.source) + extension;
    }
    std::string bytes(image.image.begin(), image.image.end());
    if (bytes.empty() && image.bufferView >= 0) {
        bytes = buffer_view_bytes(model_, image.bufferView, what + ": image");
    }
    if (bytes.empty() && !image.uri.empty() && image.uri.rfind("data:", 0) != 0) {
        // A file tinygltf could not read (it warns and leaves the image empty): named.
        const std::filesystem::path file = path_.parent_path() / image.uri;
        throw Error(what + ": image " + std::to_string(texture.source) + " '" +
                    excerpt(image.uri, 200) +
                    "': " + (std::filesystem::exists(file) ? "cannot be read" : "file not found") +
                    " (beside the glTF file)");
    }
    if (bytes.empty()) {
        throw Error(what + ": image " + std::to_string(texture.source) + " has no data");
    }
    Texture decoded = decode_texture(bytes, path_.parent_path() / name);
    if (decoded.max_value > 1.0f) {
        throw Error(what + ": base colour texture values reach " +
                    std::to_string(decoded.max_value) + " (albedo > 1)");
    }
    decoded.encoded = bytes;
    scene_.textures.push_back(std::move(decoded));
    textures_[texture.source] = static_cast<int>(scene_.textures.size() - 1);
    return textures_[texture.source];
}

}  // namespace rc
