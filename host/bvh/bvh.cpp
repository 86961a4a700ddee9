#include "bvh/bvh.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "bvh/bvh_flatten.h"
#include "bvh/embree_build.h"
#include "util/error.h"

namespace rc {
namespace {

shared::BvhNode empty_node() {
    shared::BvhNode node{};
    const float inf = std::numeric_limits<float>::infinity();
    node.lower_x = node.lower_y = node.lower_z = {inf, inf, inf, inf};
    node.upper_x = node.upper_y = node.upper_z = {-inf, -inf, -inf, -inf};
    node.child = {0, 0, 0, 0};
    node.count = {0, 0, 0, 0};
    return node;
}

void set_lane(shared::BvhNode& node, unsigned lane, const RTCBounds& b, int child, int count) {
    (&node.lower_x.x)[lane] = b.lower_x;
    (&node.upper_x.x)[lane] = b.upper_x;
    (&node.lower_y.x)[lane] = b.lower_y;
    (&node.upper_y.x)[lane] = b.upper_y;
    (&node.lower_z.x)[lane] = b.lower_z;
    (&node.upper_z.x)[lane] = b.upper_z;
    (&node.child.x)[lane] = child;
    (&node.count.x)[lane] = count;
}

class Bvh4Flattener {
   public:
    Bvh4Flattener(const TriangleMesh& mesh, Bvh& bvh) : mesh_(mesh), bvh_(bvh) {}

    // Appends the node and its subtree depth first; returns its index.
    int flatten(const InnerBuildNode& build, unsigned depth) {
        if (build.child_count > 4) {
            throw Error("the 4-wide BVH got a node of " + std::to_string(build.child_count) +
                        " children");
        }
        bvh_.depth = std::max(bvh_.depth, depth);
        const int index = static_cast<int>(bvh_.nodes.size());
        bvh_.nodes.push_back(empty_node());
        for (unsigned lane = 0; lane < build.child_count; ++lane) {
            const BuildNode* child = build.children[lane];
            if (child->is_leaf) {
                const auto& leaf = *static_cast<const LeafBuildNode*>(child);
                const unsigned first = append_leaf_triangles(leaf, mesh_, bvh_);
                set_lane(bvh_.nodes[index], lane, build.bounds[lane], ~static_cast<int>(first),
                         static_cast<int>(leaf.count));
            } else {
                const int child_index =
                    flatten(*static_cast<const InnerBuildNode*>(child), depth + 1);
                set_lane(bvh_.nodes[index], lane, build.bounds[lane], child_index, 0);
            }
        }
        return index;
    }

   private:
    const TriangleMesh& mesh_;
    Bvh& bvh_;
};

// Embree's settings per layout: the 4-wide layout takes leaves of 1 to 4 triangles; the wide
// one leaves of up to 8 (two packets), kept whole down to 8 triangles, each started packet of
// four costing one intersection (docs/bvh.md has the measurements behind these).
EmbreeBuildSettings build_settings(BvhLayout layout) {
    EmbreeBuildSettings settings;
    if (layout == BvhLayout::kWide) {
        settings.branching_factor = RC_WIDE_BVH_WIDTH;
        settings.min_leaf_size = RC_WIDE_BVH_MAX_LEAF_SIZE;
        settings.max_leaf_size = RC_WIDE_BVH_MAX_LEAF_SIZE;
        settings.sah_block_size = 4;
    }
    return settings;
}

}  // namespace

unsigned append_leaf_triangles(const LeafBuildNode& leaf, const TriangleMesh& mesh, Bvh& bvh) {
    ++bvh.leaf_count;
    const auto first = static_cast<unsigned>(bvh.triangles.size());
    for (unsigned i = 0; i < leaf.count; ++i) {
        const unsigned primitive = leaf.primitives[i];
        const glm::uvec3& t = mesh.triangles[primitive];
        const glm::vec3& a = mesh.positions[t.x];
        const glm::vec3& b = mesh.positions[t.y];
        const glm::vec3& c = mesh.positions[t.z];
        shared::Triangle triangle{};
        triangle.v0 = {a.x, a.y, a.z, shared::rc_as_float(primitive)};
        triangle.v1 = {b.x, b.y, b.z, 0.0f};
        triangle.v2 = {c.x, c.y, c.z, 0.0f};
        bvh.triangle_of_primitive[primitive] = static_cast<unsigned>(bvh.triangles.size());
        bvh.triangles.push_back(triangle);
    }
    return first;
}

void flatten_bvh4(const BuildNode& root, const TriangleMesh& mesh, Bvh& bvh) {
    if (!root.is_leaf) {
        Bvh4Flattener(mesh, bvh).flatten(static_cast<const InnerBuildNode&>(root), 1);
        return;
    }
    // A tree that is one leaf becomes a root with that leaf in lane 0.
    const auto& leaf = static_cast<const LeafBuildNode&>(root);
    bvh.nodes.push_back(empty_node());
    const unsigned first = append_leaf_triangles(leaf, mesh, bvh);
    set_lane(bvh.nodes[0], 0, leaf_bounds(leaf, mesh), ~static_cast<int>(first),
             static_cast<int>(leaf.count));
}

size_t Bvh::node_count() const {
    return layout == BvhLayout::kWide ? wide_nodes.size() : nodes.size();
}

size_t Bvh::node_bytes() const {
    return nodes.size() * sizeof(shared::BvhNode) + wide_nodes.size() * sizeof(shared::WideBvhNode);
}

size_t Bvh::leaf_bytes() const {
    return layout == BvhLayout::kWide ? packets.size() * sizeof(shared::TrianglePacket)
                                      : triangles.size() * sizeof(shared::Triangle);
}

size_t Bvh::wide_packet_offset() const {
    return (wide_nodes.size() * sizeof(shared::WideBvhNode) + sizeof(shared::TrianglePacket) - 1) /
           sizeof(shared::TrianglePacket);
}

size_t Bvh::device_bytes() const {
    size_t bytes = triangles.size() * sizeof(shared::Triangle) +
                   triangle_of_primitive.size() * sizeof(unsigned);
    if (layout == BvhLayout::kWide) {
        bytes += (wide_packet_offset() + packets.size()) * sizeof(shared::TrianglePacket);
    } else {
        bytes += node_bytes();
    }
    return bytes;
}

Bvh build_bvh(const TriangleMesh& mesh, BvhLayout layout) {
    const auto start = std::chrono::steady_clock::now();
    const EmbreeBuildSettings settings = build_settings(layout);
    if (mesh.triangles.size() > static_cast<size_t>(std::numeric_limits<int>::max() / 8)) {
        throw Error("too many triangles for the BVH: " + std::to_string(mesh.triangles.size()));
    }
    Bvh bvh;
    bvh.layout = layout;
    bvh.triangle_of_primitive.assign(mesh.triangles.size(), 0);
    if (mesh.triangles.empty()) {
        // An empty scene: a root with no children.
        if (layout == BvhLayout::kWide) {
            bvh.wide_nodes.push_back(empty_wide_node());
        } else {
            bvh.nodes.push_back(empty_node());
        }
        return bvh;
    }
    {
        const EmbreeBuild build(mesh, settings);
        if (layout == BvhLayout::kWide) {
            flatten_wide(build.root(), mesh, bvh);
        } else {
            flatten_bvh4(build.root(), mesh, bvh);
        }
    }
    if (bvh.triangles.size() != mesh.triangles.size()) {
        throw Error("BVH build lost triangles: " + std::to_string(bvh.triangles.size()) + " of " +
                    std::to_string(mesh.triangles.size()));
    }
    bvh.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return bvh;
}

}  // namespace rc
