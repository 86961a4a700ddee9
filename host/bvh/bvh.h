// The BVH the kernels traverse (docs/bvh.md), built by Embree's generic builder (rtcBuildBVH,
// binned SAH) through callbacks and flattened into the arrays of one layout: the 4-wide BVH of
// float boxes (BvhNode) or the compressed 8-wide BVH (WideBvhNode, bvh/wide_bvh.h).
#pragma once

#include <vector>

#include "device/bvh_layout.h"
#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc {

struct Bvh {
    BvhLayout layout = BvhLayout::kBvh4;
    std::vector<shared::BvhNode> nodes;           // layout bvh4: node 0 is the root
    std::vector<shared::WideBvhNode> wide_nodes;  // layout wide: node 0 is the root
    // Layout wide: the leaves' triangles, one packet a leaf. On the device they follow the nodes
    // in one buffer, from packet index wide_packet_offset() on (WideBvhNode.packet_base
    // counts packets from the buffer's start).
    std::vector<shared::TrianglePacket> packets;
    std::vector<shared::Triangle> triangles;      // in leaf order (bvh4's leaves; shading)
    std::vector<unsigned> triangle_of_primitive;  // primitive index -> index in `triangles`
    unsigned depth = 0;                           // levels of inner nodes
    size_t leaf_count = 0;
    double build_seconds = 0.0;

    size_t node_count() const;
    size_t node_bytes() const;  // the node array of the layout
    size_t leaf_bytes() const;  // the leaf triangles the traversal reads
    size_t wide_packet_offset() const;
    size_t device_bytes() const;
};

// Builds the BVH over the mesh's triangles in `layout`; primitive i is mesh.triangles[i]. The
// mesh must hold finite positions only (the loaders guarantee it).
Bvh build_bvh(const TriangleMesh& mesh, BvhLayout layout);

}  // namespace rc
