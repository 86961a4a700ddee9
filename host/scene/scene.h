// A loaded scene (docs/scene-format.md): its description (camera, materials, textures, shapes in
// their own space with transforms, emitters, animation, render defaults) and the world-space
// data of the current frame that the BVH and the kernels consume.
#pragma once

#include <filesystem>
#include <functional>
#include <glm/mat4x4.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/animation.h"
#include "scene/camera.h"
#include "scene/emitter.h"
#include "scene/material.h"
#include "scene/render_settings.h"
#include "scene/texture.h"
#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc {

// Every world-space position (vertices, emitters, after transforms and animation) lies within
// [-kMaxWorldCoordinate, kMaxWorldCoordinate] on each axis (docs/scene-format.md): beyond it,
// squared distances in the kernels and bounds in Embree's BVH build overflow single precision.
inline constexpr float kMaxWorldCoordinate = 1e12f;
// The least extent (bounding box diagonal) of a scene's triangles in world space, 2^-42, about
// 2.3e-13: the device's single-precision ray/triangle test multiplies three coordinates, whose
// product underflows float's normal range (2^-126) below it. A scene without extent (no
// triangles, or one point) is not bound by it.
inline constexpr float kMinSceneExtent = 0x1p-42f;

struct Shape {
    std::string name;
    std::string type;  // "obj", "rectangle", "cube", "sphere" or "generated"
    std::filesystem::path file;
    TriangleMesh mesh;           // object space; materials: slots into `materials`
    std::vector<int> materials;  // slot -> scene material index (one slot when mesh has none)
    // Area-light radiance per material slot (a zero vector: not emitting); empty: none emit.
    std::vector<glm::vec3> emission;
    glm::mat4 transform{1.0f};
    bool flip_normals = false;

    // The world range of the current frame.
    size_t first_triangle = 0;
    size_t triangle_count = 0;
};

// The world-space light list of a frame, in the device layout, with its selection distribution.
struct LightSet {
    std::vector<shared::Light> lights;
    std::vector<float> cdf;           // selection by power
    std::vector<unsigned> triangles;  // primitives of area lights
    std::vector<float> triangle_cdf;  // cumulative area within each area light
    int environment = -1;             // index of the constant environment, or -1
};

struct Scene {
    std::filesystem::path path;
    Camera camera;  // at the current frame
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Shape> shapes;
    std::vector<Emitter> emitters;
    Animation animation;
    RenderSettings render;
    size_t dropped_degenerate = 0;  // zero-area triangles removed while loading
    size_t dropped_repeated = 0;    // triangles repeating an earlier one of their shape, removed

    // World data of the current frame.
    double frame = 0.0;
    TriangleMesh mesh;  // positions and triangles: the primitive index is the triangle index
    std::vector<glm::vec3> normals;                // world vertex normals (indexed by `shading`)
    std::vector<glm::vec2> uvs;                    // texture coordinates (indexed by `shading`)
    std::vector<shared::TriangleShading> shading;  // per primitive
    std::vector<unsigned> triangle_shape;          // per primitive
    LightSet lights;

    // Adds a shape (degenerate triangles dropped and counted); a scene without materials gets the
    // default one (diffuse, reflectance 0.5).
    void add_shape(Shape shape);
    // Rebuilds the world data (geometry, shading, lights, camera) for `frame`.
    void set_frame(double frame);

    Camera base_camera;  // the camera as the scene file gives it, before animation
};

// Completes a loaded scene: poses it at `frame`; Error naming the scene's file when it has no
// triangles (none given, or all degenerate) or the frame cannot be built.
void pose_loaded_scene(Scene& scene, double frame);

// A scene imported from `path` (glTF, pbrt-v4): `build` fills it in, then it is posed at frame 0
// (pose_loaded_scene).
Scene imported_scene(const std::filesystem::path& path, const std::function<void(Scene&)>& build);

// The index of the default material (diffuse 0.5), added on first use.
int default_material(Scene& scene);

}  // namespace rc
