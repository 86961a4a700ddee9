// The 4-wide BVH the kernels traverse (docs/bvh.md), built by Embree's generic builder
// (rtcBuildBVH, binned SAH) through callbacks into our node layout and flattened depth first.
#pragma once

#include <vector>

#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc {

struct BvhBuildOptions {
    unsigned max_leaf_size = 4;  // at most RC_BVH_MAX_LEAF_SIZE
    float traversal_cost = 1.0f;
    float intersection_cost = 1.0f;
};

struct Bvh {
    std::vector<shared::BvhNode> nodes;           // node 0 is the root
    std::vector<shared::Triangle> triangles;      // in leaf order
    std::vector<unsigned> triangle_of_primitive;  // primitive index -> index in `triangles`
    unsigned depth = 0;                           // levels of inner nodes
    size_t leaf_count = 0;
    double build_seconds = 0.0;

    size_t device_bytes() const;
};

// Builds the BVH over the mesh's triangles; primitive i is mesh.triangles[i]. The mesh must hold
// finite positions only (the loaders guarantee it).
Bvh build_bvh(const TriangleMesh& mesh, const BvhBuildOptions& options = {});

}  // namespace rc
