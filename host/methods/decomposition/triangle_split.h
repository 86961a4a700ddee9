// The near field's triangles (Arikan, Forsyth and O'Brien 2005, §5: "To avoid problems caused by
// large triangles that have significant portions within and without a distance alpha, triangles
// larger than alpha are split into smaller ones"; course, "Implementation Details 2/3"), and the
// trees that find the split triangle a point of a scene triangle lies on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/triangle_mesh.h"
#include "shared/decomposition.h"

namespace rc {

// The split of a mesh: its triangles and, per scene triangle (primitive), the root of the tree of
// shared::SplitNode that halved it (a leaf when it was not split).
struct TriangleSplit {
    std::vector<shared::NearTriangle> triangles;
    std::vector<shared::SplitNode> nodes;
    std::vector<uint32_t> roots;  // per primitive: its tree's root in `nodes`
};

// The mesh's triangles, each split at the midpoint of its longest edge, recursively, until no
// edge is longer than `alpha`; in primitive order, each triangle's pieces depth first. The
// halves keep their parent's winding (its front side). Error (exit status 2, naming --alpha) when
// that would make more than `max_triangles`.
TriangleSplit split_triangle_tree(const TriangleMesh& mesh, float alpha, size_t max_triangles);

// The triangles of split_triangle_tree.
std::vector<shared::NearTriangle> split_triangles(const TriangleMesh& mesh, float alpha,
                                                  size_t max_triangles);

// The split triangle (index into split.triangles) that point x of primitive `primitive` lies on,
// by descending its tree (the host's twin of rc_decomp_split_triangle_of).
uint32_t split_triangle_of(const TriangleSplit& split, uint32_t primitive, const glm::vec3& x);

}  // namespace rc
