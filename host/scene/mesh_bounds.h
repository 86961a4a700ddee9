// The extent of a triangle mesh's vertices.
#pragma once

#include "scene/triangle_mesh.h"

namespace rc {

// The length of the diagonal of the axis-aligned box around the mesh's vertices (0 without any).
float mesh_diagonal(const TriangleMesh& mesh);

}  // namespace rc
