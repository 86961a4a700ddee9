// The extent of a triangle mesh's vertices.
#pragma once

#include <string>

#include "scene/triangle_mesh.h"

namespace rc {

// The length of the diagonal of the axis-aligned box around the mesh's vertices (0 without any).
float mesh_diagonal(const TriangleMesh& mesh);

// Error (rc::Error) when the mesh spans more than a point but less than `least` (its diagonal):
// "<who>the scene's extent (its bounding box's diagonal)<where> is D scene units, below
// <least_name> (L): <why>".
void check_least_extent(const TriangleMesh& mesh, float least, const std::string& who,
                        const std::string& where, const std::string& least_name,
                        const std::string& why);

}  // namespace rc
