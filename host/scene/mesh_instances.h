// Instancing kept through `radcache convert`: the shapes whose object-space meshes are the same
// (positions, triangles, normals, uvs and material slots equal bit for bit, as every node of one
// glTF mesh or every use of one pbrt ObjectBegin gives) share one mesh file.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/scene.h"

namespace rc {

// For each shape, the index of the first shape with the same mesh (itself when it is the first).
std::vector<size_t> first_shape_with_mesh(const std::vector<Shape>& shapes);

}  // namespace rc
