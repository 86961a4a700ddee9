#include "scene/scene_loader.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <map>
#include <set>

#include "scene/environment_map.h"
#include "scene/generated_meshes.h"
#include "scene/gltf_loader.h"
#include "scene/json_reader.h"
#include "scene/obj_loader.h"
#include "scene/pbrt_loader.h"
#include "scene/transform.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"
#include "util/scale_free.h"
#include "util/text.h"

namespace rc {
namespace {

std::string format_vec3(glm::vec3 v) {
    return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) +
           "]";
}

// A colour: one number (grey) or [r, g, b]; every component in [min, max].
glm::vec3 parse_colour(const JsonReader& reader, const std::string& key, glm::vec3 fallback,
                       float min, float max) {
    if (!reader.has(key)) {
        return fallback;
    }
    const glm::vec3 colour =
        reader.value().at(key).is_number() ? glm::vec3(reader.number(key)) : reader.vec3(key);
    for (int c = 0; c < 3; ++c) {
        if (colour[c] < min || colour[c] > max) {
            reader.fail(key, "component " + std::to_string(c) + " = " + std::to_string(colour[c]) +
                                 " outside [" + std::to_string(min) + ", " + std::to_string(max) +
                                 "]");
        }
    }
    return colour;
}

class SceneParser {
   public:
    SceneParser(const std::filesystem::path& path, const SceneFiles& files, Scene& scene)
        : file_(path.string()), dir_(path.parent_path()), files_(files), scene_(scene) {}

    void parse(const JsonReader& root) {
        root.allow_only({"camera", "materials", "shapes", "emitters", "animation", "render"});
        scene_.base_camera = parse_camera(root.object("camera"));
        if (root.has("materials")) {
            const JsonReader materials = root.object("materials");
            for (const auto& item : materials.value().items()) {
                const JsonReader material = materials.object(item.key());
                material_index_[item.key()] = static_cast<int>(scene_.materials.size());
                scene_.materials.push_back(parse_material(material, item.key()));
            }
        }
        for (const JsonReader& shape : root.array("shapes")) {
            parse_shape(shape);
        }
        if (root.has("emitters")) {
            for (const JsonReader& emitter : root.array("emitters")) {
                parse_emitter(emitter);
            }
        }
        if (root.has("animation")) {
            parse_animation(root.object("animation"));
        }
        if (root.has("render")) {
            const JsonReader render = root.object("render");
            for (const auto& item : render.value().items()) {
                scene_.render.set(item.key(), item.value(), file_ + ": render");
            }
        }
    }

   private:
    FovAxis parse_fov_axis(const JsonReader& reader) {
        const std::string axis = reader.string("fov_axis", "x");
        if (axis == "x") return FovAxis::kX;
        if (axis == "y") return FovAxis::kY;
        if (axis == "diagonal") return FovAxis::kDiagonal;
        if (axis == "smaller") return FovAxis::kSmaller;
        if (axis == "larger") return FovAxis::kLarger;
        reader.fail("fov_axis",
                    "unknown value '" + excerpt(axis) + "' (x, y, diagonal, smaller, larger)");
    }

    // camera.filter: {"type": "box"|"tent"|"gaussian", "radius": pixels (default: the type's)}.
    PixelFilter parse_filter(const JsonReader& reader) {
        reader.allow_only({"type", "radius"});
        PixelFilter filter;
        const std::string name = reader.string("type");
        filter.type = pixel_filter_type(name);
        if (filter.type < 0) {
            reader.fail("type", "expected \"box\", \"tent\" or \"gaussian\", got \"" +
                                    excerpt(name) + "\"");
        }
        filter.radius = reader.number("radius", default_filter_radius(filter.type));
        if (!(filter.radius >= kMinFilterRadius && filter.radius <= kMaxFilterRadius)) {
            reader.fail("radius", "must lie in [" + std::to_string(kMinFilterRadius) + ", " +
                                      std::to_string(kMaxFilterRadius) + "] pixels, got " +
                                      std::to_string(filter.radius));
        }
        return filter;
    }

    Camera parse_camera(const JsonReader& reader) {
        reader.allow_only(
            {"position", "look_at", "up", "fov", "fov_axis", "resolution", "filter", "sampler"});
        Camera camera;
        camera.position = reader.vec3("position");
        camera.look_at = reader.vec3("look_at");
        camera.up = reader.vec3("up", glm::vec3(0.0f, 1.0f, 0.0f));
        camera.fov_degrees = reader.number("fov");
        camera.fov_axis = parse_fov_axis(reader);
        const glm::ivec2 resolution =
            reader.ivec2("resolution", glm::ivec2(512, 512), 1, kMaxImageSide);
        camera.width = resolution.x;
        camera.height = resolution.y;
        if (reader.has("filter")) {
            camera.filter = parse_filter(reader.object("filter"));
        }
        if (reader.has("sampler")) {
            const std::string name = reader.string("sampler");
            camera.sampler = pixel_sampler_type(name);
            if (camera.sampler < 0) {
                reader.fail("sampler",
                            "expected \"independent\" or \"sobol\", got \"" + excerpt(name) + "\"");
            }
        }
        if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f)) {
            reader.fail("fov", "must lie strictly between 0 and 180 degrees, got " +
                                   std::to_string(camera.fov_degrees));
        }
        const glm::vec3 forward = camera.look_at - camera.position;
        if (is_zero_vector(forward)) {
            reader.fail("look_at", "coincides with position");
        }
        if (is_zero_vector(glm::vec3(glm::cross(glm::dvec3(forward), glm::dvec3(camera.up))))) {
            reader.fail("up", "is parallel to the viewing direction");
        }
        return camera;
    }

    int texture(const std::filesystem::path& path) {
        const std::string key = path.lexically_normal().string();
        const auto found = texture_index_.find(key);
        if (found != texture_index_.end()) {
            return found->second;
        }
        scene_.textures.push_back(load_texture(path, files_));
        texture_index_[key] = static_cast<int>(scene_.textures.size() - 1);
        return texture_index_[key];
    }

    // A reflectance: a colour, or {"type": "bitmap", "filename": F} (a texture).
    glm::vec3 parse_reflectance(const JsonReader& reader, const std::string& key,
                                glm::vec3 fallback, int* texture_index) {
        if (reader.has(key) && reader.value().at(key).is_object()) {
            const JsonReader bitmap = reader.object(key);
            bitmap.allow_only({"type", "filename", "scale"});
            if (bitmap.string("type") != "bitmap") {
                bitmap.fail("type", "unknown texture type '" + excerpt(bitmap.string("type")) +
                                        "' (known: bitmap)");
            }
            const std::filesystem::path image = dir_ / bitmap.string("filename");
            if (!files_.exists(image)) {
                bitmap.fail("filename", "texture file '" + excerpt(image.string()) + "' not found");
            }
            *texture_index = texture(image);
            const Texture& t = scene_.textures[*texture_index];
            if (t.max_value > 1.0f) {  // times a scale in [0, 1]
                bitmap.fail("filename", "texture values reach " + std::to_string(t.max_value) +
                                            " (albedo > 1)");
            }
            return parse_colour(bitmap, "scale", glm::vec3(1.0f), 0.0f, 1.0f);
        }
        return parse_colour(reader, key, fallback, 0.0f, 1.0f);
    }

    // A microfacet roughness: "alpha", or "alpha_x" and "alpha_y" (anisotropic), in [0, 1];
    // 0 (the default) is smooth.
    static void parse_alpha(const JsonReader& reader, Material* material) {
        const float alpha = reader.number("alpha", 0.0f);
        material->alpha_x = reader.number("alpha_x", alpha);
        material->alpha_y = reader.number("alpha_y", alpha);
        for (const char* key : {"alpha", "alpha_x", "alpha_y"}) {
            const float value = reader.number(key, 0.0f);
            if (!(value >= 0.0f && value <= 1.0f)) {
                reader.fail(key, "must lie in [0, 1], got " + std::to_string(value));
            }
        }
    }

    // The conductor: "eta" and "k" per channel, or a normal-incidence "reflectance".
    void parse_conductor(const JsonReader& reader, Material* material) {
        reader.allow_only({"type", "eta", "k", "reflectance", "alpha", "alpha_x", "alpha_y"});
        material->kind = MaterialKind::kConductor;
        material->specular = glm::vec3(1.0f);
        parse_alpha(reader, material);
        if (reader.has("reflectance")) {
            if (reader.has("eta") || reader.has("k")) {
                reader.fail("reflectance", "give either eta and k or reflectance, not both");
            }
            set_conductor_reflectance(
                *material, parse_colour(reader, "reflectance", glm::vec3(1.0f), 0.0f, 1.0f));
            return;
        }
        if (!reader.has("eta") || !reader.has("k")) {
            reader.fail("a conductor needs \"eta\" and \"k\" (or \"reflectance\")");
        }
        material->eta = parse_colour(reader, "eta", glm::vec3(1.0f), 1e-4f, 100.0f);
        material->k = parse_colour(reader, "k", glm::vec3(0.0f), 0.0f, 100.0f);
    }

    // A dielectric: its index "ior" (inside over outside, in (1, 10]; 1 passes light
    // unchanged) and, for "dielectric", a roughness.
    void parse_dielectric(const JsonReader& reader, const std::string& type, Material* material) {
        const bool thin = type == "thindielectric";
        if (thin) {
            reader.allow_only({"type", "ior"});
        } else {
            reader.allow_only({"type", "ior", "alpha", "alpha_x", "alpha_y"});
            parse_alpha(reader, material);
        }
        material->kind = thin ? MaterialKind::kThinDielectric : MaterialKind::kDielectric;
        material->diffuse = glm::vec3(0.0f);
        material->specular = glm::vec3(1.0f);
        material->ior = reader.number("ior", 1.5f);
        if (!(material->ior >= 1.0f && material->ior <= 10.0f)) {
            reader.fail("ior", "must lie in [1, 10], got " + std::to_string(material->ior));
        }
    }

    Material parse_material(const JsonReader& reader, const std::string& name) {
        Material material;
        material.name = name;
        const std::string type = reader.string("type");
        if (type == "conductor") {
            material.diffuse = glm::vec3(0.0f);
            parse_conductor(reader, &material);
            return material;
        }
        if (type == "dielectric" || type == "thindielectric") {
            parse_dielectric(reader, type, &material);
            return material;
        }
        if (type == "diffusetransmission") {
            reader.allow_only({"type", "reflectance", "transmittance"});
            material.kind = MaterialKind::kDiffuseTransmission;
            material.diffuse = glm::vec3(0.0f);
            material.specular = parse_colour(reader, "reflectance", glm::vec3(0.25f), 0.0f, 1.0f);
            material.transmittance =
                parse_colour(reader, "transmittance", glm::vec3(0.25f), 0.0f, 1.0f);
            const glm::vec3 total = material.specular + material.transmittance;
            if (total.r > 1.0f || total.g > 1.0f || total.b > 1.0f) {
                reader.fail("reflectance + transmittance = " + format_vec3(total) +
                            " exceeds 1 (albedo > 1 breaks energy conservation)");
            }
            return material;
        }
        if (type == "diffuse") {
            reader.allow_only({"type", "reflectance"});
            material.kind = MaterialKind::kDiffuse;
            material.diffuse = parse_reflectance(reader, "reflectance", glm::vec3(0.5f),
                                                 &material.diffuse_texture);
            return material;
        }
        if (type == "phong") {
            reader.allow_only({"type", "diffuse", "specular", "exponent"});
            material.kind = MaterialKind::kPhong;
            material.exponent = reader.number("exponent", 30.0f);
            if (material.exponent < 0.0f || material.exponent > 1e6f) {
                reader.fail("exponent",
                            "must lie in [0, 1e6], got " + std::to_string(material.exponent));
            }
        } else if (type == "ward") {
            reader.allow_only({"type", "diffuse", "specular", "alpha_x", "alpha_y"});
            material.kind = MaterialKind::kWard;
            material.alpha_x = reader.number("alpha_x", 0.1f);
            material.alpha_y = reader.number("alpha_y", 0.1f);
            for (const char* key : {"alpha_x", "alpha_y"}) {
                const float alpha = reader.number(key, 0.1f);
                if (alpha < 0.001f || alpha > 1.0f) {
                    reader.fail(key, "must lie in [0.001, 1], got " + std::to_string(alpha));
                }
            }
        } else {
            reader.fail("type",
                        "unknown material type '" + excerpt(type) +
                            "' (diffuse, phong, ward, conductor, dielectric, thindielectric, "
                            "diffusetransmission)");
        }
        material.diffuse =
            parse_reflectance(reader, "diffuse", glm::vec3(0.5f), &material.diffuse_texture);
        material.specular = parse_colour(reader, "specular", glm::vec3(0.2f), 0.0f, 1.0f);
        const glm::vec3 total = material.diffuse + material.specular;
        if (total.r > 1.0f || total.g > 1.0f || total.b > 1.0f) {
            reader.fail("diffuse + specular = " + format_vec3(total) +
                        " exceeds 1 (albedo > 1 breaks energy conservation)");
        }
        return material;
    }

    int material_named(const JsonReader& reader, const std::string& key) {
        const std::string name = reader.string(key);
        const auto found = material_index_.find(name);
        if (found == material_index_.end()) {
            reader.fail(key, "unknown material '" + excerpt(name) + "'");
        }
        return found->second;
    }

    // Materials of an OBJ's MTL library: Kd (or map_Kd), Ks with Ns (phong when Ks > 0).
    int obj_material(const ObjMaterial& m, const JsonReader& reader) {
        Material material;
        material.name = m.name;
        material.diffuse = m.kd;
        if (!m.map_kd.empty()) {
            material.diffuse_texture = texture(m.map_kd);
            material.diffuse = glm::vec3(1.0f);
        }
        if (m.ks != glm::vec3(0.0f)) {
            material.kind = MaterialKind::kPhong;
            material.specular = m.ks;
            material.exponent = m.ns;
        }
        const glm::vec3 total = material.diffuse + material.specular;
        if (glm::any(glm::lessThan(material.diffuse, glm::vec3(0.0f))) ||
            glm::any(glm::lessThan(material.specular, glm::vec3(0.0f))) || total.r > 1.0f ||
            total.g > 1.0f || total.b > 1.0f) {
            reader.fail("file", "MTL material '" + excerpt(m.name) + "': Kd + Ks = " +
                                    format_vec3(total) + " is negative or exceeds 1");
        }
        scene_.materials.push_back(material);
        return static_cast<int>(scene_.materials.size() - 1);
    }

    glm::vec3 parse_area_emitter(const JsonReader& reader) {
        const JsonReader emitter = reader.object("emitter");
        emitter.allow_only({"type", "radiance"});
        if (emitter.string("type") != "area") {
            emitter.fail("type", "unknown shape emitter '" + excerpt(emitter.string("type")) +
                                     "' (known: area)");
        }
        return parse_colour(emitter, "radiance", glm::vec3(1.0f), 0.0f, 1e9f);
    }

    void parse_shape(const JsonReader& reader) {
        const std::string type = reader.string("type");
        Shape shape;
        shape.type = type;
        std::vector<std::string> keys = {"type",      "name",         "material",
                                         "transform", "flip_normals", "emitter"};
        if (type == "obj") {
            keys.push_back("file");
        } else if (type == "sphere") {
            keys.insert(keys.end(), {"center", "radius"});
        } else if (type != "rectangle" && type != "cube") {
            reader.fail("type", "unknown shape type '" + excerpt(type) +
                                    "' (obj, rectangle, cube, sphere)");
        }
        for (const auto& item : reader.value().items()) {
            if (std::find(keys.begin(), keys.end(), item.key()) == keys.end()) {
                std::string list;
                for (const std::string& k : keys) {
                    list += (list.empty() ? "" : ", ") + k;
                }
                reader.fail(item.key(),
                            "unknown key for a " + type + " shape (known: " + list + ")");
            }
        }
        const int material = reader.has("material") ? material_named(reader, "material") : -1;
        const std::optional<glm::vec3> emission =
            reader.has("emitter") ? std::optional<glm::vec3>(parse_area_emitter(reader))
                                  : std::nullopt;
        if (type == "obj") {
            shape.file = dir_ / reader.string("file");
            if (!files_.exists(shape.file)) {
                reader.fail("file", "mesh file '" + excerpt(shape.file.string()) + "' not found");
            }
            ObjData obj = load_obj(shape.file, files_);
            for (const std::string& warning : obj.warnings) {
                log_warning(warning);
            }
            shape.mesh = std::move(obj.mesh);
            // Slots: the MTL materials, then one for faces without a material.
            const int unassigned = static_cast<int>(obj.materials.size());
            for (int& slot : shape.mesh.materials) {
                slot = slot < 0 ? unassigned : slot;
            }
            for (const ObjMaterial& m : obj.materials) {
                shape.materials.push_back(material >= 0 ? material : obj_material(m, reader));
                shape.emission.push_back(emission ? *emission : m.ke);
            }
            shape.materials.push_back(material >= 0 ? material : default_material(scene_));
            shape.emission.push_back(emission ? *emission : glm::vec3(0.0f));
            for (const ObjMaterial& m : obj.materials) {
                if (glm::any(glm::lessThan(m.ke, glm::vec3(0.0f)))) {
                    reader.fail("file", "MTL material '" + excerpt(m.name) + "': Ke " +
                                            format_vec3(m.ke) + " is negative");
                }
            }
        } else {
            if (type == "rectangle") {
                shape.mesh = make_rectangle();
            } else if (type == "cube") {
                shape.mesh = make_cube();
            } else {
                const float radius = reader.number("radius", 1.0f);
                if (!(radius > 0.0f)) {
                    reader.fail("radius", "must be positive, got " + std::to_string(radius));
                }
                shape.mesh = make_uv_sphere(reader.vec3("center", glm::vec3(0.0f)), radius);
            }
            shape.materials.push_back(material >= 0 ? material : default_material(scene_));
            if (emission) {
                shape.emission.push_back(*emission);
            }
        }
        shape.name = reader.string("name", type == "obj"
                                               ? shape.file.stem().string()
                                               : type + "_" + std::to_string(scene_.shapes.size()));
        if (!shape_names_.insert(shape.name).second) {
            reader.fail("name", "a shape named '" + excerpt(shape.name) + "' already exists");
        }
        shape.transform = parse_transform(reader, "transform");
        if (reader.has("flip_normals")) {
            if (!reader.value().at("flip_normals").is_boolean()) {
                reader.fail("flip_normals", "expected true or false");
            }
            shape.flip_normals = reader.value().at("flip_normals").get<bool>();
        }
        const size_t triangles_before = shape.mesh.triangle_count();
        scene_.add_shape(std::move(shape));
        const Shape& added = scene_.shapes.back();
        if (added.mesh.triangle_count() == 0) {
            reader.fail(triangles_before == 0 ? std::string("the shape has no triangles")
                                              : "all " + std::to_string(triangles_before) +
                                                    " triangles of the shape have zero area");
        }
    }

    void parse_emitter(const JsonReader& reader) {
        const std::string type = reader.string("type");
        Emitter emitter;
        if (type == "point") {
            reader.allow_only({"type", "name", "position", "intensity"});
            emitter.kind = EmitterKind::kPoint;
            emitter.position = reader.vec3("position");
            emitter.intensity = parse_colour(reader, "intensity", glm::vec3(1.0f), 0.0f, 1e12f);
        } else if (type == "spot") {
            reader.allow_only(
                {"type", "name", "position", "look_at", "intensity", "cutoff_angle", "beam_width"});
            emitter.kind = EmitterKind::kSpot;
            emitter.position = reader.vec3("position");
            emitter.look_at = reader.vec3("look_at");
            if (is_zero_vector(emitter.look_at - emitter.position)) {
                reader.fail("look_at", "coincides with position");
            }
            emitter.intensity = parse_colour(reader, "intensity", glm::vec3(1.0f), 0.0f, 1e12f);
            emitter.cutoff_angle = reader.number("cutoff_angle", 20.0f);
            emitter.beam_width = reader.number("beam_width", emitter.cutoff_angle * 0.75f);
            if (!(emitter.cutoff_angle > 0.0f && emitter.cutoff_angle < 90.0f)) {
                reader.fail("cutoff_angle", "must lie in (0, 90) degrees");
            }
            if (!(emitter.beam_width > 0.0f && emitter.beam_width < emitter.cutoff_angle)) {
                reader.fail("beam_width", "must lie in (0, cutoff_angle) degrees");
            }
        } else if (type == "distant") {
            reader.allow_only({"type", "name", "direction", "irradiance"});
            emitter.kind = EmitterKind::kDistant;
            emitter.direction = reader.vec3("direction");
            if (is_zero_vector(emitter.direction)) {
                reader.fail("direction", "must not be the zero vector");
            }
            emitter.direction = glm::normalize(emitter.direction);
            emitter.irradiance = parse_colour(reader, "irradiance", glm::vec3(1.0f), 0.0f, 1e9f);
        } else if (type == "constant" || type == "envmap") {
            for (const Emitter& other : scene_.emitters) {
                if (other.kind == EmitterKind::kConstant) {
                    reader.fail("type", "a scene has at most one environment (constant or envmap)");
                }
            }
            emitter.kind = EmitterKind::kConstant;
            if (type == "constant") {
                reader.allow_only({"type", "name", "radiance"});
                emitter.radiance = parse_colour(reader, "radiance", glm::vec3(1.0f), 0.0f, 1e9f);
            } else {
                parse_environment_map(reader, emitter);
            }
        } else {
            reader.fail("type", "unknown emitter type '" + excerpt(type) +
                                    "' (point, spot, distant, constant, envmap)");
        }
        emitter.name = reader.string("name", type + "_" + std::to_string(scene_.emitters.size()));
        if (!emitter_names_.insert(emitter.name).second) {
            reader.fail("name", "an emitter named '" + excerpt(emitter.name) + "' already exists");
        }
        scene_.emitters.push_back(emitter);
    }

    // {"type": "envmap", "filename": F, "scale": s, "mapping": "latlong" | "equal-area"}.
    void parse_environment_map(const JsonReader& reader, Emitter& emitter) {
        reader.allow_only({"type", "name", "filename", "scale", "mapping"});
        const std::filesystem::path image = dir_ / reader.string("filename");
        if (!files_.exists(image)) {
            reader.fail("filename", "environment map '" + excerpt(image.string()) + "' not found");
        }
        const int mapping = map_mapping_of(reader.string("mapping", "latlong"));
        if (mapping < 0) {
            reader.fail("mapping", "expected latlong or equal-area, got '" +
                                       excerpt(reader.string("mapping")) + "'");
        }
        const glm::vec3 scale = parse_colour(reader, "scale", glm::vec3(1.0f), 0.0f, 1e9f);
        try {
            load_environment_map(scene_, emitter, image, files_, scale, mapping);
        } catch (const Error& error) {
            reader.fail("filename", error.what());
        }
    }

    void parse_animation(const JsonReader& reader) {
        reader.allow_only({"frame_start", "frame_end", "fps", "tracks"});
        Animation& animation = scene_.animation;
        animation.frame_start = reader.integer("frame_start", 0, -kMaxFrameNumber, kMaxFrameNumber);
        animation.frame_end = reader.integer("frame_end", static_cast<int>(animation.frame_start),
                                             -kMaxFrameNumber, kMaxFrameNumber);
        animation.fps = reader.number("fps", 24.0f);
        if (animation.frame_end < animation.frame_start) {
            reader.fail("frame_end", "is before frame_start");
        }
        if (!(animation.fps > 0.0)) {
            reader.fail("fps", "must be positive");
        }
        std::set<std::string> targets;  // one track a target: a second would be dropped
        for (const JsonReader& track_reader : reader.array("tracks")) {
            track_reader.allow_only({"target", "keyframes"});
            AnimationTrack track;
            const std::string target = track_reader.string("target");
            if (!targets.insert(target).second) {
                track_reader.fail("target", "a second track for '" + excerpt(target) +
                                                "': give each target one track of keyframes");
            }
            if (target == "camera") {
                track.target = TrackTarget::kCamera;
            } else if (target.rfind("shape:", 0) == 0) {
                track.target = TrackTarget::kShape;
                track.name = target.substr(6);
                if (shape_names_.count(track.name) == 0) {
                    track_reader.fail("target", "no shape named '" + excerpt(track.name) + "'");
                }
            } else if (target.rfind("emitter:", 0) == 0) {
                track.target = TrackTarget::kEmitter;
                track.name = target.substr(8);
                if (emitter_names_.count(track.name) == 0) {
                    track_reader.fail("target", "no emitter named '" + excerpt(track.name) + "'");
                }
            } else {
                track_reader.fail("target",
                                  "expected \"camera\", \"shape:NAME\" or "
                                  "\"emitter:NAME\", got '" +
                                      excerpt(target) + "'");
            }
            for (const JsonReader& key_reader : track_reader.array("keyframes")) {
                key_reader.allow_only({"frame", "translate", "rotate"});
                Keyframe key;
                key.frame = key_reader.number("frame");
                key.translate = key_reader.vec3("translate", glm::vec3(0.0f));
                if (key_reader.has("rotate")) {
                    const JsonReader rotate = key_reader.object("rotate");
                    rotate.allow_only({"axis", "angle"});
                    const glm::vec3 axis = rotate.vec3("axis");
                    if (glm::length(axis) == 0.0f) {
                        rotate.fail("axis", "is the zero vector");
                    }
                    key.rotate =
                        glm::angleAxis(glm::radians(rotate.number("angle")), glm::normalize(axis));
                }
                if (!track.keyframes.empty() && key.frame <= track.keyframes.back().frame) {
                    key_reader.fail("frame", "keyframes must have increasing frames");
                }
                track.keyframes.push_back(key);
            }
            if (track.keyframes.empty()) {
                track_reader.fail("keyframes", "needs at least one keyframe");
            }
            animation.tracks.push_back(std::move(track));
        }
    }

    std::string file_;
    std::filesystem::path dir_;
    const SceneFiles& files_;
    Scene& scene_;
    std::map<std::string, int> material_index_;
    std::map<std::string, int> texture_index_;
    std::set<std::string> shape_names_;
    std::set<std::string> emitter_names_;
};

// A scene that renders black without a word: warned, an error under --strict.
void warn_unless_lit(const Scene& scene) {
    const bool lit = std::any_of(
        scene.lights.lights.begin(), scene.lights.lights.end(), [](const shared::Light& light) {
            return light.radiance.x > 0.0f || light.radiance.y > 0.0f || light.radiance.z > 0.0f;
        });
    if (!lit) {
        log_warning(scene.path.string() +
                    ": the scene has no emitter that gives light: the image will be black "
                    "(render --environment R,G,B lights it with a constant sky)");
    }
}

// The scene of `path`, posed at its first frame (load_scene without the overrides and checks).
Scene read_scene(const std::filesystem::path& path, const SceneFiles& files,
                 const std::string& camera) {
    if (is_gltf_path(path)) {
        return load_gltf_scene(path, files, camera);
    }
    if (!camera.empty()) {
        throw Error("--camera " + excerpt(camera) + ": applies to glTF scenes only", kExitUsage);
    }
    if (is_pbrt_path(path)) {
        return load_pbrt_scene(path, files);
    }
    if (!files.exists(path)) {
        throw Error(path.string() + ": scene file not found");
    }
    const std::string file = path.string();
    const nlohmann::json document =
        parse_json(files.read(path, kMaxSceneFileBytes, "scene file"), file);
    const JsonReader root(document, file);
    Scene scene;
    scene.path = path;
    SceneParser(path, files, scene).parse(root);
    pose_loaded_scene(scene, scene.animation.frame_start);
    return scene;
}

// The scene's environment replaced by `environment` (the one it has, or a new one, as a glTF
// viewer lights a model), and the scene posed again for its lights.
void set_environment(Scene& scene, const SceneFiles& files,
                     const EnvironmentOverride& environment) {
    Emitter* sky = nullptr;
    for (Emitter& emitter : scene.emitters) {
        if (emitter.kind == EmitterKind::kConstant) {
            sky = &emitter;
        }
    }
    if (sky == nullptr) {
        Emitter added;
        added.name = "--environment";
        scene.emitters.push_back(added);
        sky = &scene.emitters.back();
    }
    const std::string name = sky->name;
    *sky = Emitter{};
    sky->name = name;
    sky->kind = EmitterKind::kConstant;
    sky->radiance = environment.radiance;
    if (!environment.map.empty()) {
        if (!files.exists(environment.map)) {
            throw Error("--environment " + excerpt(environment.map.string()) +
                            ": environment map not found",
                        kExitUsage);
        }
        load_environment_map(scene, *sky, environment.map, files, glm::vec3(1.0f), RC_MAP_LATLONG);
    }
    pose_loaded_scene(scene, scene.animation.frame_start);
}

}  // namespace

bool is_imported_scene_path(const std::filesystem::path& path) {
    return is_gltf_path(path) || is_pbrt_path(path);
}

Scene load_scene(const std::filesystem::path& path, const SceneFiles& files,
                 const std::string& camera, const std::optional<EnvironmentOverride>& environment) {
    Scene scene = read_scene(path, files, camera);
    if (environment) {
        set_environment(scene, files, *environment);
    }
    warn_unless_lit(scene);
    return scene;
}

}  // namespace rc
