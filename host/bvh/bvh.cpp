#include "bvh/bvh.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <limits>
#include <new>

#include "bvh/embree_device.h"
#include "util/error.h"

namespace rc {
namespace {

// Temporary tree made by Embree's callbacks in its thread-local memory, freed with the RTCBVH.
struct BuildNode {
    bool is_leaf;
};
struct InnerBuildNode : BuildNode {
    unsigned child_count;
    BuildNode* children[4];
    RTCBounds bounds[4];
};
struct LeafBuildNode : BuildNode {
    unsigned count;
    unsigned primitives[RC_BVH_MAX_LEAF_SIZE];
};

void* create_node(RTCThreadLocalAllocator allocator, unsigned child_count, void*) {
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(InnerBuildNode), 16);
    auto* node = new (memory) InnerBuildNode{};
    node->is_leaf = false;
    node->child_count = child_count;
    return node;
}

void set_node_children(void* node_ptr, void** children, unsigned child_count, void*) {
    auto* node = static_cast<InnerBuildNode*>(node_ptr);
    for (unsigned i = 0; i < child_count; ++i) {
        node->children[i] = static_cast<BuildNode*>(children[i]);
    }
}

void set_node_bounds(void* node_ptr, const RTCBounds** bounds, unsigned child_count, void*) {
    auto* node = static_cast<InnerBuildNode*>(node_ptr);
    for (unsigned i = 0; i < child_count; ++i) {
        node->bounds[i] = *bounds[i];
    }
}

void* create_leaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* primitives,
                  size_t count, void* user) {
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(LeafBuildNode), 16);
    auto* leaf = new (memory) LeafBuildNode{};
    leaf->is_leaf = true;
    if (count > RC_BVH_MAX_LEAF_SIZE) {
        // Exceptions must not cross Embree's C interface: flag it, fail after the build.
        static_cast<std::atomic<bool>*>(user)->store(true);
        count = RC_BVH_MAX_LEAF_SIZE;
    }
    leaf->count = static_cast<unsigned>(count);
    // Embree reorders the primitive array during the build: copy the ids out now.
    for (size_t i = 0; i < count; ++i) {
        leaf->primitives[i] = primitives[i].primID;
    }
    return leaf;
}

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
    float* lower_x = &node.lower_x.x;
    float* upper_x = &node.upper_x.x;
    float* lower_y = &node.lower_y.x;
    float* upper_y = &node.upper_y.x;
    float* lower_z = &node.lower_z.x;
    float* upper_z = &node.upper_z.x;
    lower_x[lane] = b.lower_x;
    upper_x[lane] = b.upper_x;
    lower_y[lane] = b.lower_y;
    upper_y[lane] = b.upper_y;
    lower_z[lane] = b.lower_z;
    upper_z[lane] = b.upper_z;
    (&node.child.x)[lane] = child;
    (&node.count.x)[lane] = count;
}

class Flattener {
   public:
    Flattener(const TriangleMesh& mesh, Bvh& bvh) : mesh_(mesh), bvh_(bvh) {}

    // Appends the node and its subtree depth first; returns its index.
    int flatten(const InnerBuildNode& build, unsigned depth) {
        bvh_.depth = std::max(bvh_.depth, depth);
        const int index = static_cast<int>(bvh_.nodes.size());
        bvh_.nodes.push_back(empty_node());
        for (unsigned lane = 0; lane < build.child_count; ++lane) {
            const BuildNode* child = build.children[lane];
            if (child->is_leaf) {
                const auto& leaf = *static_cast<const LeafBuildNode*>(child);
                const int first = static_cast<int>(bvh_.triangles.size());
                append_leaf(leaf);
                set_lane(bvh_.nodes[index], lane, build.bounds[lane], ~first,
                         static_cast<int>(leaf.count));
            } else {
                const int child_index =
                    flatten(*static_cast<const InnerBuildNode*>(child), depth + 1);
                set_lane(bvh_.nodes[index], lane, build.bounds[lane], child_index, 0);
            }
        }
        return index;
    }

    void append_leaf(const LeafBuildNode& leaf) {
        ++bvh_.leaf_count;
        for (unsigned i = 0; i < leaf.count; ++i) {
            const unsigned primitive = leaf.primitives[i];
            const glm::uvec3& t = mesh_.triangles[primitive];
            shared::Triangle triangle{};
            const glm::vec3& a = mesh_.positions[t.x];
            const glm::vec3& b = mesh_.positions[t.y];
            const glm::vec3& c = mesh_.positions[t.z];
            triangle.v0 = {a.x, a.y, a.z, shared::rc_as_float(primitive)};
            triangle.v1 = {b.x, b.y, b.z, 0.0f};
            triangle.v2 = {c.x, c.y, c.z, 0.0f};
            bvh_.triangle_of_primitive[primitive] = static_cast<unsigned>(bvh_.triangles.size());
            bvh_.triangles.push_back(triangle);
        }
    }

   private:
    const TriangleMesh& mesh_;
    Bvh& bvh_;
};

}  // namespace

size_t Bvh::device_bytes() const {
    return nodes.size() * sizeof(shared::BvhNode) + triangles.size() * sizeof(shared::Triangle) +
           triangle_of_primitive.size() * sizeof(unsigned);
}

Bvh build_bvh(const TriangleMesh& mesh, const BvhBuildOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (options.max_leaf_size < 1 || options.max_leaf_size > RC_BVH_MAX_LEAF_SIZE) {
        throw Error("BVH leaf size " + std::to_string(options.max_leaf_size) + " outside [1, " +
                    std::to_string(RC_BVH_MAX_LEAF_SIZE) + "]");
    }
    if (mesh.triangles.size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
        throw Error("too many triangles for the BVH: " + std::to_string(mesh.triangles.size()));
    }
    Bvh bvh;
    bvh.triangle_of_primitive.assign(mesh.triangles.size(), 0);
    if (mesh.triangles.empty()) {
        bvh.nodes.push_back(empty_node());
        return bvh;
    }

    std::vector<RTCBuildPrimitive> primitives(mesh.triangles.size());
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::vec3 lower =
            glm::min(mesh.positions[t.x], glm::min(mesh.positions[t.y], mesh.positions[t.z]));
        const glm::vec3 upper =
            glm::max(mesh.positions[t.x], glm::max(mesh.positions[t.y], mesh.positions[t.z]));
        primitives[i] = {lower.x, lower.y, lower.z, 0,
                         upper.x, upper.y, upper.z, static_cast<unsigned>(i)};
    }

    EmbreeDevice device;
    RTCBVH embree_bvh = rtcNewBVH(device.handle());
    device.check("rtcNewBVH");
    RTCBuildArguments arguments = rtcDefaultBuildArguments();
    arguments.byteSize = sizeof(arguments);
    arguments.buildQuality = RTC_BUILD_QUALITY_HIGH;
    arguments.maxBranchingFactor = 4;
    arguments.maxDepth = RC_BVH_MAX_DEPTH;
    arguments.sahBlockSize = 1;
    arguments.minLeafSize = 1;
    arguments.maxLeafSize = options.max_leaf_size;
    arguments.traversalCost = options.traversal_cost;
    arguments.intersectionCost = options.intersection_cost;
    arguments.bvh = embree_bvh;
    arguments.primitives = primitives.data();
    arguments.primitiveCount = primitives.size();
    arguments.primitiveArrayCapacity = primitives.size();
    arguments.createNode = create_node;
    arguments.setNodeChildren = set_node_children;
    arguments.setNodeBounds = set_node_bounds;
    arguments.createLeaf = create_leaf;
    std::atomic<bool> leaf_overflow{false};
    arguments.userPtr = &leaf_overflow;
    void* root = rtcBuildBVH(&arguments);
    try {
        device.check("rtcBuildBVH");
        if (leaf_overflow.load()) {
            throw Error("rtcBuildBVH made a leaf larger than " +
                        std::to_string(RC_BVH_MAX_LEAF_SIZE) + " triangles");
        }
        if (root == nullptr) {
            throw Error("rtcBuildBVH returned no tree");
        }
        Flattener flattener(mesh, bvh);
        const auto* root_node = static_cast<const BuildNode*>(root);
        if (root_node->is_leaf) {
            // A tree that is one leaf becomes a root with that leaf in lane 0.
            const auto& leaf = *static_cast<const LeafBuildNode*>(root_node);
            bvh.nodes.push_back(empty_node());
            flattener.append_leaf(leaf);
            RTCBounds bounds{};
            bounds.lower_x = bounds.lower_y = bounds.lower_z = std::numeric_limits<float>::max();
            bounds.upper_x = bounds.upper_y = bounds.upper_z = -std::numeric_limits<float>::max();
            for (const shared::Triangle& t : bvh.triangles) {
                for (const shared::float4* v : {&t.v0, &t.v1, &t.v2}) {
                    bounds.lower_x = std::min(bounds.lower_x, v->x);
                    bounds.lower_y = std::min(bounds.lower_y, v->y);
                    bounds.lower_z = std::min(bounds.lower_z, v->z);
                    bounds.upper_x = std::max(bounds.upper_x, v->x);
                    bounds.upper_y = std::max(bounds.upper_y, v->y);
                    bounds.upper_z = std::max(bounds.upper_z, v->z);
                }
            }
            set_lane(bvh.nodes[0], 0, bounds, ~0, static_cast<int>(leaf.count));
        } else {
            flattener.flatten(*static_cast<const InnerBuildNode*>(root_node), 1);
        }
    } catch (...) {
        rtcReleaseBVH(embree_bvh);
        throw;
    }
    rtcReleaseBVH(embree_bvh);
    if (bvh.triangles.size() != mesh.triangles.size()) {
        throw Error("BVH build lost triangles: " + std::to_string(bvh.triangles.size()) + " of " +
                    std::to_string(mesh.triangles.size()));
    }
    bvh.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return bvh;
}

}  // namespace rc
