#include "scene/scene_loader.h"

#include <glm/geometric.hpp>

#include "scene/json_reader.h"
#include "scene/obj_loader.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

FovAxis parse_fov_axis(const JsonReader& reader) {
    const std::string axis = reader.string("fov_axis", "x");
    if (axis == "x") return FovAxis::kX;
    if (axis == "y") return FovAxis::kY;
    if (axis == "diagonal") return FovAxis::kDiagonal;
    if (axis == "smaller") return FovAxis::kSmaller;
    if (axis == "larger") return FovAxis::kLarger;
    reader.fail("fov_axis", "unknown value '" + axis + "' (x, y, diagonal, smaller, larger)");
}

Camera parse_camera(const JsonReader& reader) {
    reader.allow_only({"position", "look_at", "up", "fov", "fov_axis", "resolution"});
    Camera camera;
    camera.position = reader.vec3("position");
    camera.look_at = reader.vec3("look_at");
    camera.up = reader.vec3("up", glm::vec3(0.0f, 1.0f, 0.0f));
    camera.fov_degrees = reader.number("fov");
    camera.fov_axis = parse_fov_axis(reader);
    const glm::ivec2 resolution = reader.ivec2("resolution", glm::ivec2(512, 512));
    if (resolution.x <= 0 || resolution.y <= 0) {
        reader.fail("resolution", "width and height must be positive, got " +
                                      std::to_string(resolution.x) + "x" +
                                      std::to_string(resolution.y));
    }
    camera.width = resolution.x;
    camera.height = resolution.y;
    if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f)) {
        reader.fail("fov", "must lie strictly between 0 and 180 degrees, got " +
                               std::to_string(camera.fov_degrees));
    }
    const glm::vec3 forward = camera.look_at - camera.position;
    if (glm::length(forward) == 0.0f) {
        reader.fail("look_at", "coincides with position");
    }
    if (glm::length(glm::cross(forward, camera.up)) == 0.0f) {
        reader.fail("up", "is parallel to the viewing direction");
    }
    return camera;
}

void parse_shape(const JsonReader& reader, const std::filesystem::path& scene_dir, Scene& scene) {
    const std::string type = reader.string("type");
    if (type != "obj") {
        reader.fail("type", "unknown shape type '" + type + "' (known: obj)");
    }
    reader.allow_only({"type", "name", "file"});
    Shape shape;
    shape.type = type;
    shape.file = scene_dir / reader.string("file");
    shape.name = reader.string("name", shape.file.stem().string());
    if (!std::filesystem::is_regular_file(shape.file)) {
        reader.fail("file", "mesh file '" + shape.file.string() + "' not found");
    }
    TriangleMesh mesh = load_obj(shape.file);
    scene.add_shape(std::move(shape), std::move(mesh));
}

}  // namespace

Scene load_scene(const std::filesystem::path& path) {
    if (!std::filesystem::is_regular_file(path)) {
        throw Error(path.string() + ": scene file not found");
    }
    const std::string file = path.string();
    const nlohmann::json document = parse_json(read_file(path), file);
    const JsonReader root(document, file);
    root.allow_only({"camera", "shapes"});

    Scene scene;
    scene.path = path;
    scene.camera = parse_camera(root.object("camera"));
    const std::filesystem::path scene_dir = path.parent_path();
    for (const JsonReader& shape : root.array("shapes")) {
        parse_shape(shape, scene_dir, scene);
    }
    if (scene.mesh.triangle_count() == 0) {
        throw Error(file + ": the scene has no triangles");
    }
    return scene;
}

}  // namespace rc
