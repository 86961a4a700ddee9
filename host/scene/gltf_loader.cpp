#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>
#include <map>
#include <set>
#include <string_view>

#include "scene/gltf_accessors.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_validate.h"
#include "scene/json_parse.h"
#include "util/error.h"
#include "util/log.h"
#include "util/scale_free.h"
#include "util/text.h"

namespace rc {

bool is_gltf_path(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".gltf" || extension == ".glb";
}

namespace {

// tinygltf reads buffers and images through the scene's files (memory in the fuzz target).
tinygltf::FsCallbacks file_callbacks(const SceneFiles& files) {
    tinygltf::FsCallbacks callbacks{};
    callbacks.user_data = const_cast<SceneFiles*>(&files);
    callbacks.FileExists = [](const std::string& path, void* user) {
        return static_cast<const SceneFiles*>(user)->exists(path);
    };
    callbacks.ExpandFilePath = [](const std::string& path, void*) { return path; };
    callbacks.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err,
                                 const std::string& path, void* user) {
        try {
            const std::string bytes =
                static_cast<const SceneFiles*>(user)->read(path, kMaxMeshFileBytes, "glTF buffer");
            out->assign(bytes.begin(), bytes.end());
            return true;
        } catch (const Error& error) {
            *err += error.what();
            return false;
        }
    };
    callbacks.WriteWholeFile = [](std::string*, const std::string&,
                                  const std::vector<unsigned char>&, void*) { return false; };
    return callbacks;
}

// Keeps an image's encoded bytes as they are: radcache decodes them itself (texture.h). An image
// in a buffer view is left to the materials, which read the view with its range checked
// (gltf_materials.cpp): tinygltf 2.7 hands its bytes over without checking that the view lies
// inside its buffer (a heap-buffer-overflow found by the gltf fuzz target,
// tests/fuzz/regressions/gltf/).
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0) {
        image->image.assign(bytes, bytes + size);
    }
    return true;
}

// The JSON text of a glTF file: the whole file, or a .glb's first chunk (header: magic, version,
// length; chunk: length, type, data), clamped to the bytes there are.
std::string_view gltf_json_text(const std::string& bytes, bool binary) {
    if (!binary) {
        return bytes;
    }
    if (bytes.size() < 20) {
        return {};
    }
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, sizeof(length));
    return std::string_view(bytes).substr(20, length);
}

tinygltf::Model read_model(const std::filesystem::path& path, const SceneFiles& files) {
    const std::string name = path.string();
    if (!files.exists(path)) {
        throw Error(name + ": scene file not found");
    }
    const std::string bytes = files.read(path, kMaxMeshFileBytes, "glTF file");
    tinygltf::TinyGLTF reader;
    reader.SetFsCallbacks(file_callbacks(files));
    reader.SetImageLoader(keep_image_bytes, nullptr);
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const std::string base = path.parent_path().string();
    const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    // tinygltf converts `extras` recursively: a document nested thousands deep overflows the
    // stack, so the JSON (a .glb's first chunk) is bounded as radcache's own scene files are.
    const std::string json_text(gltf_json_text(bytes, binary));
    if (json_nesting_depth(json_text) > kMaxJsonDepth) {
        throw Error(name + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                    " levels");
    }
    // What tinygltf would read silently wrong (duplicate keys, wrong lengths, negative offsets).
    validate_gltf_json(json_text, name);
    const bool read =
        binary ? reader.LoadBinaryFromMemory(&model, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(bytes.data()),
                                             static_cast<unsigned>(bytes.size()), base)
               : reader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                            static_cast<unsigned>(bytes.size()), base);
    if (!read) {
        std::string line = error.substr(0, error.find('\n'));
        throw Error(name + ": not a readable glTF 2.0 file: " +
                    excerpt(line.empty() ? std::string("tinygltf failed") : line, 200));
    }
    return model;
}

glm::mat4 local_matrix(const tinygltf::Node& node, const std::string& what) {
    if (node.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) {
            glm::value_ptr(m)[i] = static_cast<float>(node.matrix[i]);  // column-major, as glTF
        }
        return m;
    }
    if (!node.matrix.empty() || (!node.translation.empty() && node.translation.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4) ||
        (!node.scale.empty() && node.scale.size() != 3)) {
        throw Error(what + ": matrix, translation, rotation or scale of the wrong length");
    }
    glm::mat4 m(1.0f);
    if (!node.translation.empty()) {
        m = glm::translate(
            m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {
        const glm::quat q(
            static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
            static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        if (!(glm::length(q) > 0.0f)) {
            throw Error(what + ": rotation is not a unit quaternion");
        }
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (!node.scale.empty()) {
        m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return m;
}

class GltfSceneBuilder {
   public:
    GltfSceneBuilder(const std::filesystem::path& path, const tinygltf::Model& model, Scene& scene)
        : file_(path.string()),
          model_(model),
          scene_(scene),
          warnings_(file_),
          materials_(path, model, scene, warnings_) {}

    void build(const std::string& camera_name) {
        check_extensions();
        if (model_.scenes.empty()) {
            throw Error(file_ + ": the file has no scene");
        }
        const int index = model_.defaultScene >= 0 ? model_.defaultScene : 0;
        if (static_cast<size_t>(index) >= model_.scenes.size()) {
            throw Error(file_ + ": scene " + std::to_string(index) + " does not exist");
        }
        if (!model_.animations.empty()) {
            warn("animations", "ignored: the static pose is rendered");
        }
        for (int root : model_.scenes[index].nodes) {
            visit(root, glm::mat4(1.0f), 0, "scene " + std::to_string(index));
        }
        scene_.base_camera = choose_camera(camera_name);
    }

   private:
    void warn(const std::string& feature, const std::string& what) {
        warnings_.warn(feature, what);
    }

    void check_extensions() {
        static const std::set<std::string> supported = {
            "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_transmission",
            "KHR_materials_ior", "KHR_materials_volume"};
        for (const std::string& extension : model_.extensionsRequired) {
            if (!supported.count(extension)) {
                throw Error(file_ + ": requires the glTF extension " + excerpt(extension) +
                                ", which radcache does not support",
                            kExitUnsupported);
            }
        }
        for (const std::string& extension : model_.extensionsUsed) {
            if (!supported.count(extension)) {
                warn("extension " + excerpt(extension), "ignored");
            }
        }
    }

    // Node `index` and its children; `from` names what lists it ("scene 0", "node 3").
    void visit(int index, const glm::mat4& parent, int depth, const std::string& from) {
        const std::string what = file_ + ": node " + std::to_string(index);
        if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size()) {
            throw Error(file_ + ": " + from + " lists node " + std::to_string(index) +
                        ", which does not exist (the file has " +
                        std::to_string(model_.nodes.size()) + " nodes)");
        }
        if (depth > 256 || !on_path_.insert(index).second) {
            throw Error(what + ": the node hierarchy has a cycle (or is deeper than 256)");
        }
        const tinygltf::Node& node = model_.nodes[index];
        const glm::mat4 world = parent * local_matrix(node, what);
        if (node.skin >= 0) {
            warn("skins", "ignored: meshes are rendered in their bind pose");
        }
        if (node.mesh >= 0) {
            add_mesh(node, index, world);
        }
        if (node.camera >= 0) {
            if (static_cast<size_t>(node.camera) >= model_.cameras.size()) {
                throw Error(what + ": camera " + std::to_string(node.camera) + " does not exist");
            }
            cameras_.push_back({node.camera, index, world});
        }
        add_light(node, what, world);
        for (int child : node.children) {
            visit(child, world, depth + 1, "node " + std::to_string(index));
        }
        on_path_.erase(index);
    }

    void add_mesh(const tinygltf::Node& node, int node_index, const glm::mat4& world) {
        const std::string what = file_ + ": node " + std::to_string(node_index);
        if (static_cast<size_t>(node.mesh) >= model_.meshes.size()) {
            throw Error(what + ": mesh " + std::to_string(node.mesh) + " does not exist");
        }
        if (linear_determinant(world) == 0.0) {
            throw Error(what + ": its transform is not invertible");
        }
        const tinygltf::Mesh& mesh = model_.meshes[node.mesh];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::string where =
                what + " mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p);
            if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES) {
                warn("primitive mode " + std::to_string(primitive.mode),
                     "points, lines, strips and fans are skipped");
                continue;
            }
            if (!primitive.targets.empty()) {
                warn("morph targets", "ignored: the base shape is rendered");
            }
            Shape shape;
            shape.type = "gltf";
            shape.mesh = primitive_mesh(primitive, where);
            shape.transform = world;
            const GltfMaterial& material = materials_.get(primitive.material, where);
            if (material.tex_coord != 0) {
                warn("texCoord other than 0", "the base colour texture reads TEXCOORD_0");
            }
            shape.materials.push_back(material.index);
            if (material.emission != glm::vec3(0.0f)) {
                shape.emission.push_back(material.emission);
            }
            std::string name = node.name.empty() ? "node" + std::to_string(node_index) : node.name;
            name += "/" + std::to_string(node.mesh) + "/" + std::to_string(p);
            shape.name = name;
            for (int k = 2; !shape_names_.insert(shape.name).second; ++k) {
                shape.name = name + "#" + std::to_string(k);
            }
            scene_.add_shape(std::move(shape));
        }
    }

    TriangleMesh primitive_mesh(const tinygltf::Primitive& primitive, const std::string& where) {
        const auto attribute = [&](const char* name) {
            const auto found = primitive.attributes.find(name);
            return found == primitive.attributes.end() ? -1 : found->second;
        };
        if (attribute("POSITION") < 0) {
            throw Error(where + ": has no POSITION attribute");
        }
        TriangleMesh mesh;
        const std::vector<float> p = read_float_accessor(model_, attribute("POSITION"), 3, where);
        const size_t vertices = p.size() / 3;
        for (size_t i = 0; i < vertices; ++i) {
            mesh.positions.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
        }
        if (attribute("NORMAL") >= 0) {
            const std::vector<float> n = read_float_accessor(model_, attribute("NORMAL"), 3, where);
            if (n.size() != p.size()) {
                throw Error(where + ": NORMAL and POSITION differ in count");
            }
            for (size_t i = 0; i < vertices; ++i) {
                // Normalized as the OBJ loader does, so a converted scene shades the same.
                const glm::vec3 normal(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
                const float length =
                    std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
                mesh.normals.push_back(length > 0.0f ? normal / length : glm::vec3(0, 0, 1));
            }
        }
        if (attribute("TEXCOORD_0") >= 0) {
            const std::vector<float> t =
                read_float_accessor(model_, attribute("TEXCOORD_0"), 2, where);
            if (t.size() / 2 != vertices) {
                throw Error(where + ": TEXCOORD_0 and POSITION differ in count");
            }
            for (size_t i = 0; i < vertices; ++i) {
                mesh.uvs.emplace_back(t[2 * i], 1.0f - t[2 * i + 1]);  // glTF's v runs down
            }
        }
        std::vector<unsigned> indices;
        if (primitive.indices >= 0) {
            indices = read_index_accessor(model_, primitive.indices, where + " indices");
        } else {
            indices.resize(vertices);
            for (size_t i = 0; i < vertices; ++i) {
                indices[i] = static_cast<unsigned>(i);
            }
        }
        if (indices.size() % 3 != 0) {
            throw Error(where + ": " + std::to_string(indices.size()) +
                        " indices do not make whole triangles");
        }
        for (size_t i = 0; i < indices.size(); i += 3) {
            for (int k = 0; k < 3; ++k) {
                if (indices[i + k] >= vertices) {
                    throw Error(where + ": index " + std::to_string(indices[i + k]) +
                                " out of range (" + std::to_string(vertices) + " vertices)");
                }
            }
            mesh.triangles.emplace_back(indices[i], indices[i + 1], indices[i + 2]);
        }
        return mesh;
    }

    void add_light(const tinygltf::Node& node, const std::string& what, const glm::mat4& world) {
        const auto extension = node.extensions.find("KHR_lights_punctual");
        if (extension == node.extensions.end()) {
            return;
        }
        // The index is read as a double and range-checked before any conversion: tinygltf's
        // GetNumberAsInt converts a real such as 1e20 to int unchecked (undefined behaviour).
        const tinygltf::Value& index = extension->second.Get("light");
        const double number = index.IsNumber() ? index.GetNumberAsDouble() : -1.0;
        if (!(number >= 0.0) || number >= static_cast<double>(model_.lights.size()) ||
            number != std::floor(number)) {
            throw Error(what + ": KHR_lights_punctual names no existing light");
        }
        const tinygltf::Light& light = model_.lights[static_cast<size_t>(number)];
        Emitter emitter;
        emitter.name = "light" + std::to_string(scene_.emitters.size()) +
                       (node.name.empty() ? "" : "_" + node.name);
        glm::vec3 colour(1.0f);
        if (light.color.size() == 3) {
            colour = glm::vec3(light.color[0], light.color[1], light.color[2]);
        }
        emitter.intensity = colour * static_cast<float>(light.intensity);
        if (!(glm::all(glm::greaterThanEqual(emitter.intensity, glm::vec3(0.0f))) &&
              glm::all(glm::lessThanEqual(emitter.intensity, glm::vec3(1e12f))))) {
            throw Error(what + ": light intensity outside [0, 1e12]");
        }
        if (light.range > 0.0) {
            warn("light range", "ignored: lights fall off with the inverse square everywhere");
        }
        emitter.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
        if (light.type == "directional") {
            // KHR_lights_punctual: light travelling along the node's -z, its intensity the
            // illuminance (lux) on a surface facing it.
            const glm::vec3 axis = glm::mat3(world) * glm::vec3(0, 0, -1);
            if (!(glm::length(axis) > 0.0f) || !std::isfinite(glm::length(axis))) {
                throw Error(what + ": the directional light's transform is degenerate");
            }
            emitter.kind = EmitterKind::kDistant;
            emitter.direction = glm::normalize(axis);
            emitter.irradiance = emitter.intensity;
            emitter.intensity = glm::vec3(0.0f);
            if (!glm::all(glm::lessThanEqual(emitter.irradiance, glm::vec3(1e9f)))) {
                throw Error(what + ": directional light intensity outside [0, 1e9]");
            }
        } else if (light.type == "point") {
            emitter.kind = EmitterKind::kPoint;
        } else if (light.type == "spot") {
            emitter.kind = EmitterKind::kSpot;
            const glm::vec3 axis = glm::mat3(world) * glm::vec3(0, 0, -1);
            if (!(glm::length(axis) > 0.0f)) {
                throw Error(what + ": the spot light's transform is degenerate");
            }
            emitter.look_at = emitter.position + glm::normalize(axis);
            emitter.cutoff_angle =
                std::min(89.9f, static_cast<float>(glm::degrees(light.spot.outerConeAngle)));
            emitter.beam_width =
                std::clamp(static_cast<float>(glm::degrees(light.spot.innerConeAngle)), 1e-3f,
                           0.999f * emitter.cutoff_angle);
            if (!(emitter.cutoff_angle > 0.0f)) {
                throw Error(what + ": the spot light's outerConeAngle must be positive");
            }
            warn("spot cone falloff",
                 "radcache's spot falls off linearly in angle between "
                 "innerConeAngle and outerConeAngle");
        } else {
            warn("light type '" + excerpt(light.type) + "'",
                 "skipped (radcache has point, spot, directional, area and constant lights)");
            return;
        }
        scene_.emitters.push_back(emitter);
    }

    struct CameraNode {
        int camera;
        int node;
        glm::mat4 world;
    };

    Camera choose_camera(const std::string& name) {
        const CameraNode* chosen = cameras_.empty() ? nullptr : &cameras_.front();
        if (!name.empty()) {
            chosen = nullptr;
            for (const CameraNode& c : cameras_) {
                if (model_.cameras[c.camera].name == name || model_.nodes[c.node].name == name) {
                    chosen = &c;
                    break;
                }
            }
            if (chosen == nullptr) {
                throw Error(file_ + ": --camera " + excerpt(name) + ": no camera of that name");
            }
        }
        if (chosen == nullptr) {
            log_warning(file_ + ": the glTF scene has no camera: looking at its bounds from +z");
            return default_camera();
        }
        const tinygltf::Camera& gltf = model_.cameras[chosen->camera];
        if (gltf.type != "perspective") {
            throw Error(file_ + ": camera " + std::to_string(chosen->camera) + " is " +
                            excerpt(gltf.type) + " (radcache has perspective cameras only)",
                        kExitUnsupported);
        }
        Camera camera;
        camera.position = glm::vec3(chosen->world * glm::vec4(0, 0, 0, 1));
        const glm::vec3 forward = glm::mat3(chosen->world) * glm::vec3(0, 0, -1);
        const glm::vec3 up = glm::mat3(chosen->world) * glm::vec3(0, 1, 0);
        if (!(glm::length(forward) > 0.0f) || !(glm::length(glm::cross(forward, up)) > 0.0f)) {
            throw Error(file_ + ": the camera's node transform is degenerate");
        }
        camera.look_at = camera.position + glm::normalize(forward);
        camera.up = glm::normalize(up);
        camera.fov_degrees = static_cast<float>(glm::degrees(gltf.perspective.yfov));
        camera.fov_axis = FovAxis::kY;
        if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f)) {
            throw Error(file_ + ": camera yfov must lie in (0, pi)");
        }
        camera.height = 512;
        camera.width = 512;
        if (gltf.perspective.aspectRatio > 0.0) {
            const double width = std::round(512.0 * gltf.perspective.aspectRatio);
            if (!(width >= 1.0 && width <= double{kMaxImageSide})) {
                throw Error(file_ + ": camera aspectRatio " +
                            describe_json(gltf.perspective.aspectRatio) +
                            " makes a 512-row image " + describe_json(width) +
                            " pixels wide (1 to " + std::to_string(kMaxImageSide) + ")");
            }
            camera.width = static_cast<int>(width);
        }
        return camera;
    }

    Camera default_camera() const {
        glm::vec3 lo(INFINITY), hi(-INFINITY);
        for (const Shape& shape : scene_.shapes) {
            for (const glm::vec3& p : shape.mesh.positions) {
                const glm::vec3 w = glm::vec3(shape.transform * glm::vec4(p, 1.0f));
                lo = glm::min(lo, w);
                hi = glm::max(hi, w);
            }
        }
        Camera camera;
        if (!(lo.x <= hi.x)) {
            return camera;
        }
        const glm::vec3 centre = 0.5f * (lo + hi);
        // Relative to the scene at any scale (double where float's squares underflow), 1 for a
        // single point.
        float size = glm::length(hi - lo);
        if (!(size > 0.0f)) {
            size = static_cast<float>(glm::length(glm::dvec3(hi) - glm::dvec3(lo)));
        }
        size = size > 0.0f ? size : 1.0f;
        camera.position = centre + glm::vec3(0.0f, 0.0f, 1.5f * size);
        camera.look_at = centre;
        camera.fov_degrees = 45.0f;
        return camera;
    }

    std::string file_;
    const tinygltf::Model& model_;
    Scene& scene_;
    GltfWarnings warnings_;
    GltfMaterials materials_;
    std::set<int> on_path_;
    std::set<std::string> shape_names_;
    std::vector<CameraNode> cameras_;
};

}  // namespace

Scene load_gltf_scene(const std::filesystem::path& path, const SceneFiles& files,
                      const std::string& camera) {
    const tinygltf::Model model = read_model(path, files);
    return imported_scene(
        path, [&](Scene& scene) { GltfSceneBuilder(path, model, scene).build(camera); });
}

}  // namespace rc
