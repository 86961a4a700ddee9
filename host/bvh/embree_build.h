// Embree's generic BVH builder (rtcBuildBVH, binned SAH) run through callbacks into a temporary
// tree in Embree's thread-local memory, which the BVH layouts then flatten (bvh/bvh.cpp,
// bvh/wide_bvh.cpp). The tree lives as long as the EmbreeBuild.
#pragma once

#include <embree3/rtcore.h>

#include "bvh/embree_device.h"
#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc {

// Children of an inner node at most (Embree's builder takes branching factors up to this).
inline constexpr unsigned kMaxBuildBranching = 8;

struct BuildNode {
    bool is_leaf;
};
struct InnerBuildNode : BuildNode {
    unsigned child_count;
    const BuildNode* children[kMaxBuildBranching];
    RTCBounds bounds[kMaxBuildBranching];
};
struct LeafBuildNode : BuildNode {
    unsigned count;
    unsigned primitives[RC_BVH_MAX_LEAF_SIZE];  // the mesh's triangle indices
};

struct EmbreeBuildSettings {
    unsigned branching_factor = 4;  // 2 to kMaxBuildBranching
    unsigned min_leaf_size = 1;     // subtrees of at most this many triangles become leaves
    unsigned max_leaf_size = 4;     // min_leaf_size to RC_BVH_MAX_LEAF_SIZE
    float traversal_cost = 1.0f;
    float intersection_cost = 1.0f;
    unsigned sah_block_size = 1;  // a leaf costs intersection_cost per started block of this size
};

class EmbreeBuild {
   public:
    // Builds over the mesh's triangles (at least one; finite positions); primitive i is
    // mesh.triangles[i]. Binned SAH at RTC_BUILD_QUALITY_HIGH, depth at most RC_BVH_MAX_DEPTH.
    EmbreeBuild(const TriangleMesh& mesh, const EmbreeBuildSettings& settings);
    ~EmbreeBuild();
    EmbreeBuild(const EmbreeBuild&) = delete;
    EmbreeBuild& operator=(const EmbreeBuild&) = delete;

    const BuildNode& root() const { return *root_; }

   private:
    EmbreeDevice device_;
    RTCBVH bvh_ = nullptr;
    const BuildNode* root_ = nullptr;
};

// `bounds` grown to hold `other`.
void grow_bounds(RTCBounds& bounds, const RTCBounds& other);

// The bounds of a leaf's triangles.
RTCBounds leaf_bounds(const LeafBuildNode& leaf, const TriangleMesh& mesh);

}  // namespace rc
