// A loaded scene: camera and shapes, with every shape's triangles gathered into one world-space
// mesh (the primitive index of a triangle is its index in that mesh).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/triangle_mesh.h"

namespace rc {

struct Shape {
    std::string name;
    std::string type;  // "obj"
    std::filesystem::path file;
    size_t first_triangle = 0;  // its triangles in Scene::mesh
    size_t triangle_count = 0;
};

struct Scene {
    std::filesystem::path path;
    Camera camera;
    std::vector<Shape> shapes;
    TriangleMesh mesh;
    std::vector<unsigned> triangle_shape;  // the shape of each triangle
    size_t dropped_degenerate = 0;         // zero-area triangles removed while loading

    // Adds a shape with its triangles, dropping (and counting) degenerate ones.
    void add_shape(Shape shape, TriangleMesh triangles);
};

}  // namespace rc
