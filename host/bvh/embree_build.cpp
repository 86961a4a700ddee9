#include "bvh/embree_build.h"

#include <algorithm>
#include <atomic>
#include <glm/common.hpp>
#include <limits>
#include <new>
#include <string>
#include <vector>

#include "util/error.h"

namespace rc {
namespace {

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

std::vector<RTCBuildPrimitive> build_primitives(const TriangleMesh& mesh) {
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
    return primitives;
}

}  // namespace

EmbreeBuild::EmbreeBuild(const TriangleMesh& mesh, const EmbreeBuildSettings& settings) {
    if (settings.branching_factor < 2 || settings.branching_factor > kMaxBuildBranching) {
        throw Error("BVH branching factor " + std::to_string(settings.branching_factor) +
                    " outside [2, " + std::to_string(kMaxBuildBranching) + "]");
    }
    if (settings.min_leaf_size < 1 || settings.max_leaf_size < settings.min_leaf_size ||
        settings.max_leaf_size > RC_BVH_MAX_LEAF_SIZE) {
        throw Error("BVH leaf sizes " + std::to_string(settings.min_leaf_size) + " to " +
                    std::to_string(settings.max_leaf_size) + " outside [1, " +
                    std::to_string(RC_BVH_MAX_LEAF_SIZE) + "]");
    }
    if (mesh.triangles.empty()) {
        throw Error("rtcBuildBVH over an empty mesh");
    }
    std::vector<RTCBuildPrimitive> primitives = build_primitives(mesh);
    bvh_ = rtcNewBVH(device_.handle());
    device_.check("rtcNewBVH");
    RTCBuildArguments arguments = rtcDefaultBuildArguments();
    arguments.byteSize = sizeof(arguments);
    arguments.buildQuality = RTC_BUILD_QUALITY_HIGH;
    arguments.maxBranchingFactor = settings.branching_factor;
    arguments.maxDepth = RC_BVH_MAX_DEPTH;
    arguments.sahBlockSize = settings.sah_block_size;
    arguments.minLeafSize = settings.min_leaf_size;
    arguments.maxLeafSize = settings.max_leaf_size;
    arguments.traversalCost = settings.traversal_cost;
    arguments.intersectionCost = settings.intersection_cost;
    arguments.bvh = bvh_;
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
        device_.check("rtcBuildBVH");
        if (leaf_overflow.load()) {
            throw Error("rtcBuildBVH made a leaf larger than " +
                        std::to_string(RC_BVH_MAX_LEAF_SIZE) + " triangles");
        }
        if (root == nullptr) {
            throw Error("rtcBuildBVH returned no tree");
        }
    } catch (...) {
        rtcReleaseBVH(bvh_);
        throw;
    }
    root_ = static_cast<const BuildNode*>(root);
}

EmbreeBuild::~EmbreeBuild() { rtcReleaseBVH(bvh_); }

void grow_bounds(RTCBounds& bounds, const RTCBounds& other) {
    bounds.lower_x = std::min(bounds.lower_x, other.lower_x);
    bounds.lower_y = std::min(bounds.lower_y, other.lower_y);
    bounds.lower_z = std::min(bounds.lower_z, other.lower_z);
    bounds.upper_x = std::max(bounds.upper_x, other.upper_x);
    bounds.upper_y = std::max(bounds.upper_y, other.upper_y);
    bounds.upper_z = std::max(bounds.upper_z, other.upper_z);
}

RTCBounds leaf_bounds(const LeafBuildNode& leaf, const TriangleMesh& mesh) {
    RTCBounds bounds{};
    bounds.lower_x = bounds.lower_y = bounds.lower_z = std::numeric_limits<float>::max();
    bounds.upper_x = bounds.upper_y = bounds.upper_z = -std::numeric_limits<float>::max();
    for (unsigned i = 0; i < leaf.count; ++i) {
        const glm::uvec3& t = mesh.triangles[leaf.primitives[i]];
        for (unsigned corner = 0; corner < 3; ++corner) {
            const glm::vec3& v = mesh.positions[t[corner]];
            grow_bounds(bounds, {v.x, v.y, v.z, 0.0f, v.x, v.y, v.z, 0.0f});
        }
    }
    return bounds;
}

}  // namespace rc
