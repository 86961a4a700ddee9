#include "scene/scene_writer.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "scene/environment_map.h"
#include "scene/mesh_instances.h"
#include "scene/scene_files.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/text.h"

namespace rc {
namespace {

nlohmann::json vec3_json(glm::vec3 v) { return {v.x, v.y, v.z}; }

// `text` when the scene format can hold it (render refuses longer strings); Error naming `what`.
const std::string& limited(const std::string& text, const std::string& what) {
    if (text.size() > kMaxSceneStringBytes) {
        throw Error("convert: " + what + " is a string of " + std::to_string(text.size()) +
                    " bytes, more than the scene format's limit of " +
                    std::to_string(kMaxSceneStringBytes) + ": '" + excerpt(text) + "'");
    }
    return text;
}

// Error naming `file` when `bytes` is more than a scene may read from it (`limit`).
void check_size(const std::string& bytes, uint64_t limit, const std::filesystem::path& file,
                const std::string& what) {
    if (bytes.size() > limit) {
        throw Error("convert: " + file.string() + " would be " + std::to_string(bytes.size()) +
                    " bytes, more than the " + std::to_string(limit >> 20) + " MiB a " + what +
                    " may hold: render would refuse it");
    }
}

// Makes the folder `dir`; Error naming it (not the library's text) when it cannot be made.
void make_folder(const std::filesystem::path& dir) {
    std::error_code error;
    create_output_folder(dir, error);
    if (error) {
        throw Error("convert: " + dir.string() + ": cannot make the folder (" + error.message() +
                    ")");
    }
}

// "%.9g": nine significant digits read back to the same float.
std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string obj_text(const TriangleMesh& mesh) {
    std::ostringstream out;
    out << "# written by radcache convert\n";
    for (const glm::vec3& p : mesh.positions) {
        out << "v " << number(p.x) << ' ' << number(p.y) << ' ' << number(p.z) << '\n';
    }
    for (const glm::vec3& n : mesh.normals) {
        out << "vn " << number(n.x) << ' ' << number(n.y) << ' ' << number(n.z) << '\n';
    }
    for (const glm::vec2& t : mesh.uvs) {
        out << "vt " << number(t.x) << ' ' << number(t.y) << '\n';
    }
    const bool normals = !mesh.normals.empty();
    const bool uvs = !mesh.uvs.empty();
    for (const glm::uvec3& triangle : mesh.triangles) {
        out << 'f';
        for (int k = 0; k < 3; ++k) {
            const unsigned i = triangle[k] + 1;
            out << ' ' << i;
            if (normals || uvs) {
                out << '/' << (uvs ? std::to_string(i) : "");
            }
            if (normals) {
                out << '/' << i;
            }
        }
        out << '\n';
    }
    return out.str();
}

nlohmann::json camera_json(const Camera& camera) {
    static const char* axes[] = {"x", "y", "diagonal", "smaller", "larger"};
    return {{"position", vec3_json(camera.position)},
            {"look_at", vec3_json(camera.look_at)},
            {"up", vec3_json(camera.up)},
            {"fov", camera.fov_degrees},
            {"fov_axis", axes[static_cast<int>(camera.fov_axis)]},
            {"resolution", {camera.width, camera.height}},
            {"filter",
             {{"type", pixel_filter_name(camera.filter.type)}, {"radius", camera.filter.radius}}},
            {"sampler", pixel_sampler_name(camera.sampler)}};
}

// The render defaults that differ from RenderSettings' own (a pbrt scene's spp and max_depth).
nlohmann::json render_json(const RenderSettings& render) {
    const RenderSettings defaults;
    nlohmann::json json = nlohmann::json::object();
    if (render.method != defaults.method) json["method"] = render.method;
    if (render.spp != defaults.spp) json["spp"] = render.spp;
    if (render.time != defaults.time) json["time"] = render.time;
    if (render.max_depth != defaults.max_depth) json["max_depth"] = render.max_depth;
    if (render.rr_depth != defaults.rr_depth) json["rr_depth"] = render.rr_depth;
    if (render.seed != defaults.seed) json["seed"] = render.seed;
    if (render.exposure != defaults.exposure) json["exposure"] = render.exposure;
    return json;
}

class SceneWriter {
   public:
    SceneWriter(const Scene& scene, const std::filesystem::path& json)
        : scene_(scene),
          json_(json),
          stem_(json.stem().string()),
          first_with_mesh_(first_shape_with_mesh(scene.shapes)) {}

    void write() {
        nlohmann::json root;
        root["camera"] = camera_json(scene_.base_camera);
        root["materials"] = nlohmann::json::object();
        for (size_t m = 0; m < scene_.materials.size(); ++m) {
            const Material& material = scene_.materials[m];
            root["materials"][limited(material.name, "material " + std::to_string(m) + "'s name")] =
                material_json(material);
        }
        root["shapes"] = nlohmann::json::array();
        for (size_t i = 0; i < scene_.shapes.size(); ++i) {
            root["shapes"].push_back(shape_json(scene_.shapes[i], i));
        }
        root["emitters"] = nlohmann::json::array();
        for (const Emitter& emitter : scene_.emitters) {
            root["emitters"].push_back(emitter_json(emitter));
        }
        const nlohmann::json render = render_json(scene_.render);
        if (!render.empty()) {
            root["render"] = render;
        }
        const std::string text = root.dump(1) + "\n";
        check_size(text, kMaxSceneFileBytes, json_, "scene file");
        write_file_atomically(json_, text);
    }

   private:
    nlohmann::json reflectance_json(const Material& material) {
        if (material.diffuse_texture < 0) {
            return vec3_json(material.diffuse);
        }
        const Texture& texture = scene_.textures[material.diffuse_texture];
        if (texture.procedural) {
            throw Error("convert: material '" + material.name + "' has a procedural texture (" +
                        texture.file.string() + "), which the format cannot hold");
        }
        if (texture.encoded.empty()) {
            return {{"type", "bitmap"},
                    {"filename",
                     limited(std::filesystem::absolute(texture.file).string(),
                             "texture " + std::to_string(material.diffuse_texture) + "'s path")},
                    {"scale", vec3_json(material.diffuse)}};
        }
        const std::string relative = stem_ + "_textures/" +
                                     std::to_string(material.diffuse_texture) + "_" +
                                     texture.file.filename().string();
        limited(relative, "texture " + std::to_string(material.diffuse_texture) + "'s file name");
        make_folder(json_.parent_path() / (stem_ + "_textures"));
        write_file_atomically(json_.parent_path() / relative, texture.encoded);
        return {{"type", "bitmap"}, {"filename", relative}, {"scale", vec3_json(material.diffuse)}};
    }

    nlohmann::json material_json(const Material& material) {
        nlohmann::json json;
        if (material.kind == MaterialKind::kDiffuse) {
            return {{"type", "diffuse"}, {"reflectance", reflectance_json(material)}};
        }
        if (material.kind == MaterialKind::kDiffuseTransmission) {
            if (material.texture_targets != 0) {
                throw Error("convert: material '" + material.name +
                            "' is a textured diffuse transmitter, which the format cannot hold");
            }
            return {{"type", "diffusetransmission"},
                    {"reflectance", vec3_json(material.specular)},
                    {"transmittance", vec3_json(material.transmittance)}};
        }
        if (material.specular != glm::vec3(1.0f) && !is_reflectance_model(material)) {
            throw Error("convert: material '" + material.name +
                        "' is a tinted conductor or dielectric, which the format cannot hold");
        }
        if (material.kind == MaterialKind::kConductor) {
            return {{"type", "conductor"},
                    {"eta", vec3_json(material.eta)},
                    {"k", vec3_json(material.k)},
                    {"alpha_x", material.alpha_x},
                    {"alpha_y", material.alpha_y}};
        }
        if (material.kind == MaterialKind::kDielectric) {
            return {{"type", "dielectric"},
                    {"ior", material.ior},
                    {"alpha_x", material.alpha_x},
                    {"alpha_y", material.alpha_y}};
        }
        if (material.kind == MaterialKind::kThinDielectric) {
            return {{"type", "thindielectric"}, {"ior", material.ior}};
        }
        json["diffuse"] = reflectance_json(material);
        json["specular"] = vec3_json(material.specular);
        if (material.kind == MaterialKind::kPhong) {
            json["type"] = "phong";
            json["exponent"] = material.exponent;
        } else {
            json["type"] = "ward";
            json["alpha_x"] = material.alpha_x;
            json["alpha_y"] = material.alpha_y;
        }
        return json;
    }

    nlohmann::json shape_json(const Shape& shape, size_t index) {
        if (shape.materials.size() != 1 || shape.emission.size() > 1) {
            throw Error("convert: shape '" + shape.name +
                        "' has several material slots, which the writer cannot hold");
        }
        // Instancing kept: a mesh that an earlier shape has is that shape's file.
        const size_t first = first_with_mesh_[index];
        const std::string relative = stem_ + "_meshes/" + std::to_string(first) + ".obj";
        limited(relative, "shape " + std::to_string(index) + "'s mesh file");
        if (first == index) {
            make_folder(json_.parent_path() / (stem_ + "_meshes"));
            const std::string obj = obj_text(shape.mesh);
            check_size(obj, kMaxMeshFileBytes, json_.parent_path() / relative, "mesh file");
            write_file_atomically(json_.parent_path() / relative, obj);
        }
        nlohmann::json matrix = nlohmann::json::array();
        for (int row = 0; row < 4; ++row) {
            for (int column = 0; column < 4; ++column) {
                matrix.push_back(shape.transform[column][row]);
            }
        }
        nlohmann::json json = {
            {"type", "obj"},
            {"name", limited(shape.name, "shape " + std::to_string(index) + "'s name")},
            {"file", relative},
            {"material", scene_.materials[shape.materials[0]].name},
            {"transform", {{{"matrix", matrix}}}},
            {"flip_normals", shape.flip_normals}};
        if (!shape.emission.empty()) {
            json["emitter"] = {{"type", "area"}, {"radiance", vec3_json(shape.emission[0])}};
        }
        return json;
    }

    // An environment map as the JSON format's "envmap": its image named by absolute path. The
    // format has no frame for a map: one under a rotation (pbrt's) is refused.
    static nlohmann::json environment_map_json(const Emitter& emitter) {
        if (emitter.map_from_world != glm::mat3(1.0f)) {
            throw Error("convert: the environment map " + excerpt(emitter.map_file) +
                            " is turned (the scene format's envmap has no frame): not written",
                        kExitUnsupported);
        }
        return {{"type", "envmap"},
                {"name", limited(emitter.name, "an emitter's name")},
                {"filename", std::filesystem::absolute(emitter.map_file).string()},
                {"scale", vec3_json(emitter.map_scale)},
                {"mapping", map_mapping_name(emitter.map_mapping)}};
    }

    static nlohmann::json emitter_json(const Emitter& emitter) {
        switch (emitter.kind) {
            case EmitterKind::kPoint:
                return {{"type", "point"},
                        {"name", limited(emitter.name, "an emitter's name")},
                        {"position", vec3_json(emitter.position)},
                        {"intensity", vec3_json(emitter.intensity)}};
            case EmitterKind::kSpot:
                return {{"type", "spot"},
                        {"name", limited(emitter.name, "an emitter's name")},
                        {"position", vec3_json(emitter.position)},
                        {"look_at", vec3_json(emitter.look_at)},
                        {"intensity", vec3_json(emitter.intensity)},
                        {"cutoff_angle", emitter.cutoff_angle},
                        {"beam_width", emitter.beam_width}};
            case EmitterKind::kDistant:
                return {{"type", "distant"},
                        {"name", limited(emitter.name, "an emitter's name")},
                        {"direction", vec3_json(emitter.direction)},
                        {"irradiance", vec3_json(emitter.irradiance)}};
            default:
                if (emitter.map >= 0) {
                    return environment_map_json(emitter);
                }
                return {{"type", "constant"},
                        {"name", limited(emitter.name, "an emitter's name")},
                        {"radiance", vec3_json(emitter.radiance)}};
        }
    }

    const Scene& scene_;
    std::filesystem::path json_;
    std::string stem_;
    std::vector<size_t> first_with_mesh_;  // per shape, the first shape with its mesh
};

}  // namespace

void write_scene(const Scene& scene, const std::filesystem::path& json) {
    SceneWriter(scene, json).write();
}

}  // namespace rc
