#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

#include "scene/transform.h"
#include "util/error.h"

namespace rc {

int default_material(Scene& scene) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].name == "default") {
            return static_cast<int>(i);
        }
    }
    Material material;
    material.name = "default";
    scene.materials.push_back(material);
    return static_cast<int>(scene.materials.size() - 1);
}

void pose_loaded_scene(Scene& scene, double frame) {
    const std::string file = scene.path.string();
    if (scene.shapes.empty()) {
        throw Error(file + ": the scene has no triangles");
    }
    try {
        scene.set_frame(frame);
    } catch (const Error& error) {
        throw Error(file + ": " + error.what());
    }
    if (scene.mesh.triangle_count() == 0) {
        throw Error(file + ": the scene has no triangles");
    }
}

Scene imported_scene(const std::filesystem::path& path, const std::function<void(Scene&)>& build) {
    Scene scene;
    scene.path = path;
    build(scene);
    pose_loaded_scene(scene, 0.0);
    return scene;
}

void Scene::add_shape(Shape shape) {
    dropped_degenerate += drop_degenerate_triangles(shape.mesh);
    dropped_repeated += drop_repeated_triangles(shape.mesh);
    if (shape.materials.empty()) {
        shape.materials.push_back(default_material(*this));
    }
    shapes.push_back(std::move(shape));
}

}  // namespace rc
