// Flattening Embree's temporary tree (bvh/embree_build.h) into the arrays of a layout.
#pragma once

#include "bvh/bvh.h"
#include "bvh/embree_build.h"

namespace rc {

// Appends the leaf's triangles to bvh.triangles (v0.w: the primitive index) and records where
// each went in bvh.triangle_of_primitive; returns the index of the first.
unsigned append_leaf_triangles(const LeafBuildNode& leaf, const TriangleMesh& mesh, Bvh& bvh);

// The 4-wide layout (bvh/bvh.cpp) and the compressed 8-wide one (bvh/wide_bvh.cpp).
void flatten_bvh4(const BuildNode& root, const TriangleMesh& mesh, Bvh& bvh);
void flatten_wide(const BuildNode& root, const TriangleMesh& mesh, Bvh& bvh);

// A wide node with no children (the root of an empty scene).
shared::WideBvhNode empty_wide_node();

}  // namespace rc
