// Wavefront OBJ meshes through tinyobjloader, validated first: every vertex must be finite and
// every face index must name an existing vertex, else an error names the file and line.
#pragma once

#include <filesystem>

#include "scene/triangle_mesh.h"

namespace rc {

// Positions and triangles (polygons fan-triangulated) of every object in the file.
TriangleMesh load_obj(const std::filesystem::path& path);

}  // namespace rc
