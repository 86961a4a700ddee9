#include "scene/pbrt_materials.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <tuple>

#include "scene/pbrt_params.h"
#include "scene/spectra.h"
#include "scene/texture.h"
#include "util/error.h"
#include "util/log.h"
#include "util/text.h"

namespace rc {
namespace {

std::string in_quotes(const std::string& text) { return "\"" + excerpt(text) + "\""; }

// Why a pbrt material type has no radcache counterpart (empty: it has one).
std::string refusal(const std::string& type) {
    if (type == "diffuse" || type == "coateddiffuse" || type == "conductor" ||
        type == "dielectric" || type == "thindielectric" || type == "diffusetransmission") {
        return "";
    }
    if (type == "interface") {
        return "bounds a participating medium, and radcache has none";
    }
    return "is not supported (diffuse, coateddiffuse, conductor, dielectric, thindielectric and "
           "diffusetransmission are)";
}

// pbrt's roughness to Trowbridge-Reitz alphas along u and v: "roughness", or "uroughness" and
// "vroughness"; TrowbridgeReitzDistribution::RoughnessToAlpha (alpha = sqrt(roughness)) unless
// "remaproughness" is false.
std::pair<float, float> alphas_of(PbrtParams& params) {
    for (const char* name : {"roughness", "uroughness", "vroughness"}) {
        if (params.type_of(name) == "texture") {
            params.refuse(std::string("a textured \"") + name + "\" is not supported");
        }
    }
    const float roughness = params.get_float("roughness", 0.0f);
    float u = params.get_float("uroughness", roughness);
    float v = params.get_float("vroughness", roughness);
    if (!(u >= 0.0f && v >= 0.0f && u <= 1e3f && v <= 1e3f)) {
        params.fail("roughness must lie in [0, 1000]");
    }
    if (params.get_bool("remaproughness", true)) {
        u = std::sqrt(u);
        v = std::sqrt(v);
    }
    return {std::min(u, 1.0f), std::min(v, 1.0f)};
}

// The isotropic alpha of the same roughness (their geometric mean), for the Phong lobe of a
// coated diffuse material.
float alpha_of(PbrtParams& params) {
    const auto [u, v] = alphas_of(params);
    if (u != v) {
        log_warning(params.what() + ": anisotropic roughness (alphas " + std::to_string(u) + ", " +
                    std::to_string(v) + ") is rendered isotropic with their geometric mean");
    }
    return std::sqrt(u * v);
}

void check_unit(glm::vec3 colour, const PbrtParams& params, const std::string& name) {
    for (int c = 0; c < 3; ++c) {
        if (!(colour[c] >= 0.0f && colour[c] <= 1.0f)) {
            params.fail(in_quotes(name) + " component " + std::to_string(c) + " = " +
                        std::to_string(colour[c]) + " outside [0, 1]");
        }
    }
}

}  // namespace

void PbrtMaterials::define_texture(const PbrtDirective& directive) {
    const std::string& name = directive.strings[0];
    const std::string& kind = directive.strings[1];
    const std::string& type = directive.strings[2];
    TextureEntry entry;
    entry.what = directive.where() + ": Texture " + in_quotes(name);
    PbrtParams params(directive, entry.what + " (" + excerpt(type) + ")");
    params.read_spectrum_files(files_, dir_);
    if (kind != "spectrum" && kind != "color") {
        entry.refused = "is a " + excerpt(kind) + " texture (only spectrum textures serve, as " +
                        "diffuse reflectances)";
    } else if (type == "constant") {
        entry.value = params.get_material_spectrum("value").value_or(glm::vec3(1.0f));
        check_unit(entry.value, params, "value");
        params.warn_unused();
    } else if (type == "imagemap") {
        const std::string file = params.get_string("filename", "");
        if (file.empty()) {
            params.fail("parameter \"string filename\" is missing");
        }
        const std::string encoding = params.get_string("encoding", "sRGB");
        if (encoding != "sRGB") {
            params.refuse("encoding " + in_quotes(encoding) +
                          " is not supported (8-bit images are decoded as sRGB, float ones as "
                          "linear)");
        }
        if (params.get_bool("invert", false)) {
            params.refuse("\"invert\" is not supported");
        }
        if (params.get_string("mapping", "uv") != "uv" || params.get_float("uscale", 1) != 1 ||
            params.get_float("vscale", 1) != 1 || params.get_float("udelta", 0) != 0 ||
            params.get_float("vdelta", 0) != 0) {
            params.refuse("texture coordinate mappings other than plain \"uv\" are not supported");
        }
        if (params.get_string("wrap", "repeat") != "repeat") {
            log_warning(params.what() +
                        ": wrap modes other than \"repeat\" are not supported: "
                        "the texture repeats");
        }
        params.ignore("filter");  // radcache filters textures its own way
        params.ignore("maxanisotropy");
        entry.value = glm::vec3(params.get_float("scale", 1.0f));
        const std::filesystem::path path =
            std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : dir_ / file;
        entry.texture = load_image(path, params);
        if (scene_.textures[entry.texture].max_value * entry.value.x > 1.0f + 1e-6f) {
            params.fail("texture values times scale reach " +
                        std::to_string(scene_.textures[entry.texture].max_value * entry.value.x) +
                        " (albedo > 1)");
        }
        params.warn_unused();
    } else if (type == "checkerboard") {
        entry.texture = bake_checkerboard(params, entry.what);
        params.warn_unused();
    } else if (type == "scale") {
        scale_texture(params, entry);
        params.warn_unused();
    } else {
        entry.refused = "is of class " + in_quotes(type) +
                        " (imagemap, checkerboard, constant and scale are supported)";
    }
    textures_[name] = entry;
}

// pbrt-v4's ScaleTexture (textures.h): "tex" (a spectrum texture or value, default 1) times
// "scale" (a float, default 1), clamped to [0, 1] as pbrt-v4's materials clamp a reflectance: an
// image texture whose scaled texels stay within 1 keeps its texels under the scale, one that
// would exceed 1 is baked scaled and clamped (a warning says so).
void PbrtMaterials::scale_texture(PbrtParams& params, TextureEntry& entry) {
    if (params.type_of("scale") == "texture") {
        entry.refused = "has a textured \"scale\" (give a float)";
        params.ignore("scale");
        params.ignore("tex");
        return;
    }
    if (params.type_of("tex") == "texture") {
        const auto inner = textures_.find(params.get_string("tex", ""));
        if (inner != textures_.end() && !inner->second.refused.empty()) {
            entry.refused = "scales texture " + in_quotes(params.get_string("tex", "")) +
                            ", which " + inner->second.refused;
            return;
        }
    }
    const float scale = params.get_float("scale", 1.0f);
    if (!(scale >= 0.0f) || !std::isfinite(scale)) {
        params.fail("\"scale\" must be a finite number >= 0, got " + std::to_string(scale));
    }
    int texture = -1;
    const glm::vec3 value = reflectance(params, "tex", glm::vec3(1.0f), &texture) * scale;
    const float largest = glm::max(value.x, glm::max(value.y, value.z));
    const float peak = texture < 0 ? 1.0f : scene_.textures[texture].max_value;
    if (largest * peak <= 1.0f + 1e-6f) {
        entry.texture = texture;
        entry.value = value;
        return;
    }
    log_warning(params.what() + ": the scaled reflectance reaches " +
                std::to_string(largest * peak) + ": clamped to 1, as pbrt-v4's materials do");
    if (texture < 0) {
        entry.value = glm::min(value, glm::vec3(1.0f));
        return;
    }
    Texture baked = scene_.textures[texture];
    baked.file = entry.what;
    baked.procedural = true;
    baked.encoded.clear();
    baked.max_value = 0.0f;
    for (glm::vec4& texel : baked.texels) {
        const glm::vec3 scaled = glm::min(glm::vec3(texel) * value, glm::vec3(1.0f));
        texel = glm::vec4(scaled, texel.a);
        baked.max_value =
            glm::max(baked.max_value, glm::max(scaled.x, glm::max(scaled.y, scaled.z)));
    }
    scene_.textures.push_back(std::move(baked));
    entry.texture = static_cast<int>(scene_.textures.size() - 1);
    entry.value = glm::vec3(1.0f);
}

// pbrt-v4's 2D checkerboard (textures.cpp, Checkerboard): tex1 where floor(s) + floor(t) is even,
// tex2 elsewhere, (s, t) = (uscale u + udelta, vscale v + vdelta), baked into an image of 8 x 8
// texels a check so that radcache's uv lookup repeats it (whole scales only; the bilinear lookup
// blurs each check's edge over one texel, where pbrt-v4 filters by the ray's footprint).
int PbrtMaterials::bake_checkerboard(PbrtParams& params, const std::string& what) {
    if (params.get_int("dimension", 2) != 2 || params.get_string("mapping", "uv") != "uv") {
        params.refuse("only the 2D checkerboard with the \"uv\" mapping is supported");
    }
    for (const char* name : {"tex1", "tex2"}) {
        if (params.type_of(name) == "texture") {
            params.refuse(std::string("a checkerboard of textures (\"") + name +
                          "\") is not supported");
        }
    }
    const glm::vec3 colours[2] = {params.get_material_spectrum("tex1").value_or(glm::vec3(1.0f)),
                                  params.get_material_spectrum("tex2").value_or(glm::vec3(0.0f))};
    check_unit(colours[0], params, "tex1");
    check_unit(colours[1], params, "tex2");
    const float scale[2] = {params.get_float("uscale", 1.0f), params.get_float("vscale", 1.0f)};
    const float delta[2] = {params.get_float("udelta", 0.0f), params.get_float("vdelta", 0.0f)};
    for (int a = 0; a < 2; ++a) {
        if (!(scale[a] >= 1.0f && scale[a] <= 512.0f && scale[a] == std::floor(scale[a])) ||
            !std::isfinite(delta[a])) {
            params.refuse(
                "a checkerboard scale must be a whole number in [1, 512] (it is baked "
                "into a texture that repeats over uv [0, 1])");
        }
    }
    constexpr int kTexelsPerCheck = 8;
    Texture texture;
    texture.file = what;
    texture.procedural = true;
    texture.width = static_cast<int>(scale[0]) * kTexelsPerCheck;
    texture.height = static_cast<int>(scale[1]) * kTexelsPerCheck;
    texture.texels.resize(static_cast<size_t>(texture.width) * texture.height);
    for (int y = 0; y < texture.height; ++y) {
        const double v = 1.0 - (y + 0.5) / texture.height;  // rows top to bottom
        for (int x = 0; x < texture.width; ++x) {
            const double u = (x + 0.5) / texture.width;
            const long parity = static_cast<long>(std::floor(scale[0] * u + delta[0])) +
                                static_cast<long>(std::floor(scale[1] * v + delta[1]));
            texture.texels[static_cast<size_t>(y) * texture.width + x] =
                glm::vec4(colours[parity % 2 == 0 ? 0 : 1], 1.0f);
        }
    }
    texture.max_value = std::max(
        {colours[0].r, colours[0].g, colours[0].b, colours[1].r, colours[1].g, colours[1].b});
    scene_.textures.push_back(std::move(texture));
    return static_cast<int>(scene_.textures.size() - 1);
}

int PbrtMaterials::load_image(const std::filesystem::path& path, PbrtParams& params) {
    const std::string key = path.lexically_normal().string();
    const auto found = images_.find(key);
    if (found != images_.end()) {
        return found->second;
    }
    if (!files_.exists(path)) {
        params.fail("image file " + in_quotes(path.string()) + " not found");
    }
    scene_.textures.push_back(load_texture(path, files_));
    images_[key] = static_cast<int>(scene_.textures.size() - 1);
    return images_[key];
}

int PbrtMaterials::define(const PbrtDirective& directive) {
    Spec spec;
    spec.directive = directive;
    spec.type = directive.strings[0];
    spec.what = directive.where() + ": Material " + in_quotes(spec.type);
    specs_.push_back(std::move(spec));
    return static_cast<int>(specs_.size() - 1);
}

void PbrtMaterials::define_named(const PbrtDirective& directive) {
    const std::string& name = directive.strings[0];
    Spec spec;
    spec.directive = directive;
    spec.what = directive.where() + ": MakeNamedMaterial " + in_quotes(name);
    if (named_.count(name) != 0) {
        throw Error(spec.what +
                    ": a material of that name is already defined (pbrt-v4 refuses a "
                    "second definition)");
    }
    PbrtParams params(directive, spec.what);
    params.read_spectrum_files(files_, dir_);
    spec.type = params.get_string("type", "");
    if (spec.type.empty()) {
        params.fail("parameter \"string type\" is missing");
    }
    specs_.push_back(std::move(spec));
    named_[name] = static_cast<int>(specs_.size() - 1);
}

int PbrtMaterials::named(const PbrtDirective& directive) const {
    const auto found = named_.find(directive.strings[0]);
    if (found == named_.end()) {
        throw Error(directive.where() + ": NamedMaterial " + in_quotes(directive.strings[0]) +
                    ": no material of that name is defined");
    }
    return found->second;
}

int PbrtMaterials::scene_material(int handle) {
    if (handle < 0) {
        return default_material(scene_);
    }
    Spec& spec = specs_[handle];
    if (spec.made < 0) {
        scene_.materials.push_back(make(spec));
        spec.made = static_cast<int>(scene_.materials.size() - 1);
    }
    return spec.made;
}

glm::vec3 PbrtMaterials::reflectance(PbrtParams& params, const std::string& name,
                                     glm::vec3 fallback, int* texture) {
    if (params.type_of(name) == "texture") {
        const std::string texture_name = params.get_string(name, "");
        const auto found = textures_.find(texture_name);
        if (found == textures_.end()) {
            params.fail("texture " + in_quotes(texture_name) + " is not defined");
        }
        if (!found->second.refused.empty()) {
            params.refuse("texture " + in_quotes(texture_name) + " (" + found->second.what + ") " +
                          found->second.refused);
        }
        *texture = found->second.texture;
        return found->second.value;
    }
    const glm::vec3 colour = params.get_material_spectrum(name).value_or(fallback);
    check_unit(colour, params, name);
    return colour;
}

// pbrt-v4's DielectricMaterial and ThinDielectricMaterial: "eta" (a float, default 1.5), the
// dielectric's roughness.
void PbrtMaterials::make_dielectric(PbrtParams& params, bool thin, Material* material) {
    material->kind = thin ? MaterialKind::kThinDielectric : MaterialKind::kDielectric;
    material->diffuse = glm::vec3(0.0f);
    material->specular = glm::vec3(1.0f);
    material->ior = params.get_index_of_refraction("eta").value_or(1.5f);
    if (!(material->ior > 0.0f && material->ior <= 10.0f)) {
        params.fail("eta must lie in (0, 10], got " + std::to_string(material->ior));
    }
    if (material->ior < 1.0f) {
        material->ior = 1.0f / material->ior;  // pbrt-v4 inverts an index below 1 the same way
    }
    if (!thin) {
        std::tie(material->alpha_x, material->alpha_y) = alphas_of(params);
    }
}

// pbrt-v4's DiffuseTransmissionMaterial: "reflectance" and "transmittance" (0.25 each), both
// times "scale", clamped to [0, 1] as pbrt-v4 clamps them; textures refused.
void PbrtMaterials::make_diffuse_transmission(PbrtParams& params, Material* material) {
    material->kind = MaterialKind::kDiffuseTransmission;
    material->diffuse = glm::vec3(0.0f);
    const float scale = params.get_float("scale", 1.0f);
    if (!(scale >= 0.0f)) {
        params.fail("scale must not be negative");
    }
    // One texture may scale the reflectance, the transmittance or both (the device material has
    // one texture slot). Each lobe is its value times the scale (times the texture), clamped to 1
    // as pbrt-v4 clamps it: a textured lobe through its largest texel.
    glm::vec3 peak[2];
    for (int lobe = 0; lobe < 2; ++lobe) {
        const char* name = lobe == 0 ? "reflectance" : "transmittance";
        int texture = -1;
        glm::vec3 factor = reflectance(params, name, glm::vec3(0.25f), &texture) * scale;
        float texel_peak = 1.0f;
        if (texture >= 0) {
            if (material->diffuse_texture >= 0 && material->diffuse_texture != texture) {
                params.refuse(
                    "diffuse-transmission \"reflectance\" and \"transmittance\" from two "
                    "different textures are not supported (one texture may serve both)");
            }
            material->diffuse_texture = texture;
            material->texture_targets |=
                lobe == 0 ? RC_TEXTURE_SCALES_REFLECTANCE : RC_TEXTURE_SCALES_TRANSMITTANCE;
            texel_peak = std::max(scene_.textures[texture].max_value, 1e-30f);
        }
        factor = glm::clamp(factor * texel_peak, 0.0f, 1.0f) / texel_peak;
        peak[lobe] = factor * texel_peak;
        (lobe == 0 ? material->specular : material->transmittance) = factor;
    }
    const glm::vec3 total = peak[0] + peak[1];
    if (glm::any(glm::greaterThan(total, glm::vec3(1.0f + 1e-6f)))) {
        log_warning(params.what() + ": reflectance + transmittance exceeds 1; scaled to 1");
        const float m = std::max({total.r, total.g, total.b});
        material->specular /= m;
        material->transmittance /= m;
    }
}

// pbrt-v4's ConductorMaterial: "eta" and "k" (rgb) or a "reflectance", its roughness.
void PbrtMaterials::make_conductor(PbrtParams& params, Material* material) {
    material->kind = MaterialKind::kConductor;
    material->diffuse = glm::vec3(0.0f);
    material->specular = glm::vec3(1.0f);
    std::tie(material->alpha_x, material->alpha_y) = alphas_of(params);
    if (params.has("reflectance")) {
        int texture = -1;
        const glm::vec3 r = reflectance(params, "reflectance", glm::vec3(1.0f), &texture);
        if (texture >= 0) {
            params.refuse("a textured conductor reflectance is not supported");
        }
        set_conductor_reflectance(*material, r);
        params.ignore("eta");
        params.ignore("k");
        return;
    }
    // pbrt-v4's default conductor is copper.
    const auto eta = params.has("eta") ? params.get_material_spectrum("eta")
                                       : named_spectrum_rgb("metal-Cu-eta");
    const auto k =
        params.has("k") ? params.get_material_spectrum("k") : named_spectrum_rgb("metal-Cu-k");
    if (!eta || !k) {
        params.fail("eta and k are missing");
    }
    if (!(glm::all(glm::greaterThan(*eta, glm::vec3(0.0f))) &&
          glm::all(glm::greaterThanEqual(*k, glm::vec3(0.0f))) &&
          glm::all(glm::lessThanEqual(*eta, glm::vec3(100.0f))) &&
          glm::all(glm::lessThanEqual(*k, glm::vec3(100.0f))))) {
        params.fail("eta must lie in (0, 100] and k in [0, 100]");
    }
    material->eta = *eta;
    material->k = *k;
}

Material PbrtMaterials::make(Spec& spec) {
    const std::string why = refusal(spec.type);
    if (!why.empty()) {
        throw Error(spec.what + " " + why, kExitUnsupported);
    }
    PbrtParams params(spec.directive, spec.what);
    params.read_spectrum_files(files_, dir_);
    params.ignore("type");
    Material material;
    material.name = "pbrt" + std::to_string(scene_.materials.size()) + "_" + spec.type;
    if (spec.type == "diffuse") {
        material.diffuse =
            reflectance(params, "reflectance", glm::vec3(0.5f), &material.diffuse_texture);
    } else if (spec.type == "coateddiffuse") {
        // The coat's Fresnel reflectance at normal incidence, ((eta - 1) / (eta + 1))^2, as the
        // specular lobe; the base seen through the coat as the diffuse one.
        const float eta = params.get_float("eta", 1.5f);
        if (!(eta >= 1.0f && eta <= 10.0f)) {
            params.fail("eta must lie in [1, 10]");
        }
        const float f0 = (eta - 1.0f) * (eta - 1.0f) / ((eta + 1.0f) * (eta + 1.0f));
        const glm::vec3 base =
            reflectance(params, "reflectance", glm::vec3(0.5f), &material.diffuse_texture);
        material.kind = MaterialKind::kPhong;
        material.diffuse = (1.0f - f0) * base;
        material.specular = glm::vec3(f0);
        material.exponent = phong_exponent_of_alpha(alpha_of(params));
        if (params.get_rgb("albedo").value_or(glm::vec3(0.0f)) != glm::vec3(0.0f)) {
            log_warning(spec.what + ": the scattering medium in the coat (albedo) is ignored");
        }
        for (const char* ignored : {"thickness", "g", "maxdepth", "nsamples"}) {
            params.ignore(ignored);  // the layered simulation's own settings
        }
    } else if (spec.type == "diffusetransmission") {
        make_diffuse_transmission(params, &material);
    } else if (spec.type == "dielectric" || spec.type == "thindielectric") {
        make_dielectric(params, spec.type == "thindielectric", &material);
    } else {
        make_conductor(params, &material);
    }
    params.warn_unused();
    return material;
}

}  // namespace rc
