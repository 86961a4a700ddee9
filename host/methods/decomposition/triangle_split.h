// The near field's triangles (Arikan, Forsyth and O'Brien 2005, §5: "To avoid problems caused by
// large triangles that have significant portions within and without a distance alpha, triangles
// larger than alpha are split into smaller ones"; course, "Implementation Details 2/3").
#pragma once

#include <cstddef>
#include <vector>

#include "scene/triangle_mesh.h"
#include "shared/decomposition.h"

namespace rc {

// The mesh's triangles, each split at the midpoint of its longest edge, recursively, until no
// edge is longer than `alpha`; in primitive order, each triangle's pieces depth first. The
// halves keep their parent's winding (its front side). Error (exit status 2, naming --alpha) when
// that would make more than `max_triangles`.
std::vector<shared::NearTriangle> split_triangles(const TriangleMesh& mesh, float alpha,
                                                  size_t max_triangles);

}  // namespace rc
