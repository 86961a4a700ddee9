// The flattened BVH4 (docs/bvh.md): every triangle in exactly one leaf, bounds that contain
// what they bound, the depth bound the traversal stack relies on, and tiny trees.
#include "bvh/bvh.h"

#include <gtest/gtest.h>

#include <limits>

#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "ray_sets.h"
#include "scene/generated_meshes.h"
#include "test_support.h"

namespace rc {
namespace {

struct Box {
    float lower[3];
    float upper[3];
};

Box lane_box(const shared::BvhNode& node, int lane) {
    return {{(&node.lower_x.x)[lane], (&node.lower_y.x)[lane], (&node.lower_z.x)[lane]},
            {(&node.upper_x.x)[lane], (&node.upper_y.x)[lane], (&node.upper_z.x)[lane]}};
}

bool contains(const Box& outer, const Box& inner) {
    for (int k = 0; k < 3; ++k) {
        if (inner.lower[k] < outer.lower[k] || inner.upper[k] > outer.upper[k]) {
            return false;
        }
    }
    return true;
}

Box triangle_box(const shared::Triangle& t) {
    Box b;
    const shared::float4* v[3] = {&t.v0, &t.v1, &t.v2};
    for (int k = 0; k < 3; ++k) {
        b.lower[k] = std::numeric_limits<float>::infinity();
        b.upper[k] = -std::numeric_limits<float>::infinity();
        for (const shared::float4* p : v) {
            b.lower[k] = std::min(b.lower[k], (&p->x)[k]);
            b.upper[k] = std::max(b.upper[k], (&p->x)[k]);
        }
    }
    return b;
}

// Walks the tree checking containment; counts how often each triangle is reached.
void check_subtree(const Bvh& bvh, int node_index, unsigned depth, std::vector<int>& seen,
                   unsigned& max_depth) {
    max_depth = std::max(max_depth, depth);
    const shared::BvhNode& node = bvh.nodes[node_index];
    for (int lane = 0; lane < 4; ++lane) {
        const int child = (&node.child.x)[lane];
        const int count = (&node.count.x)[lane];
        const Box box = lane_box(node, lane);
        if (child >= 0 && count == 0 && box.lower[0] > box.upper[0]) {
            continue;  // unused lane
        }
        if (child < 0) {
            ASSERT_GE(count, 1);
            ASSERT_LE(count, RC_BVH_MAX_LEAF_SIZE);
            for (int i = ~child; i < ~child + count; ++i) {
                ASSERT_LT(static_cast<size_t>(i), bvh.triangles.size());
                EXPECT_TRUE(contains(box, triangle_box(bvh.triangles[i])));
                ++seen[i];
            }
        } else {
            ASSERT_GT(child, node_index) << "children follow their parent (depth-first order)";
            const shared::BvhNode& inner = bvh.nodes[child];
            for (int l = 0; l < 4; ++l) {
                const Box child_box = lane_box(inner, l);
                if (child_box.lower[0] <= child_box.upper[0]) {
                    EXPECT_TRUE(contains(box, child_box));
                }
            }
            check_subtree(bvh, child, depth + 1, seen, max_depth);
        }
    }
}

void check_structure(const TriangleMesh& mesh) {
    const Bvh bvh = build_bvh(mesh);
    ASSERT_EQ(bvh.triangles.size(), mesh.triangles.size());
    std::vector<int> seen(bvh.triangles.size(), 0);
    unsigned max_depth = 0;
    check_subtree(bvh, 0, 1, seen, max_depth);
    for (size_t i = 0; i < seen.size(); ++i) {
        ASSERT_EQ(seen[i], 1) << "leaf-order triangle " << i;
    }
    EXPECT_EQ(max_depth, bvh.depth);
    EXPECT_LE(bvh.depth, static_cast<unsigned>(RC_BVH_MAX_DEPTH));
    // The primitive map inverts the leaf order, and leaf triangles are the mesh's triangles.
    for (size_t p = 0; p < mesh.triangles.size(); ++p) {
        const shared::Triangle& t = bvh.triangles[bvh.triangle_of_primitive[p]];
        ASSERT_EQ(shared::rc_as_uint(t.v0.w), p);
        EXPECT_EQ(t.v1.x, mesh.positions[mesh.triangles[p].y].x);
        EXPECT_EQ(t.v2.z, mesh.positions[mesh.triangles[p].z].z);
    }
}

TEST(Bvh, CornellBoxStructure) { check_structure(test::load_cornell_box().mesh); }

TEST(Bvh, TriangleSoupStructure) {
    check_structure(make_triangle_soup(5000, 3, glm::vec3(-1.0f), glm::vec3(1.0f), 0.2f));
}

TEST(Bvh, IdenticalTrianglesStayWithinTheDepthBound) {
    // 2000 copies of one triangle: no split separates them.
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles.assign(2000, glm::uvec3(0, 1, 2));
    check_structure(mesh);
}

TEST(Bvh, SingleTriangleAndEmptyMeshesTrace) {
    TriangleMesh one;
    one.positions = {{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}};
    one.triangles = {{0, 1, 2}};
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<shared::Ray> rays = {test::make_ray({0, 0, 0}, {0, 0, 1}, 0, inf),
                                           test::make_ray({0, 0, 0}, {0, 0, -1}, 0, inf)};
    {
        const Bvh bvh = build_bvh(one);
        const DeviceBvh device_bvh(test::shared_context(), bvh);
        DeviceTracer tracer(test::shared_context(), device_bvh);
        const auto hits = tracer.trace_closest(rays);
        EXPECT_EQ(hits[0].primitive, 0u);
        EXPECT_FLOAT_EQ(hits[0].t, 2.0f);
        EXPECT_EQ(hits[1].primitive, RC_NO_HIT);
    }
    {
        const Bvh bvh = build_bvh(TriangleMesh{});
        const DeviceBvh device_bvh(test::shared_context(), bvh);
        DeviceTracer tracer(test::shared_context(), device_bvh);
        EXPECT_EQ(tracer.trace_closest(rays)[0].primitive, RC_NO_HIT);
        EXPECT_EQ(tracer.trace_any(rays)[0], 0u);
    }
}

TEST(Bvh, BarycentricsLocateTheHitPoint) {
    TriangleMesh one;
    one.positions = {{0, 0, 5}, {4, 0, 5}, {0, 2, 5}};
    one.triangles = {{0, 1, 2}};
    const Bvh bvh = build_bvh(one);
    const DeviceBvh device_bvh(test::shared_context(), bvh);
    DeviceTracer tracer(test::shared_context(), device_bvh);
    // Aim at 0.25 v1 + 0.5 v2 + 0.25 v0 = (1, 1, 5).
    const auto hits = tracer.trace_closest(
        {test::make_ray({1, 1, 0}, {0, 0, 1}, 0, std::numeric_limits<float>::infinity())});
    EXPECT_EQ(hits[0].primitive, 0u);
    EXPECT_NEAR(hits[0].u, 0.25f, 1e-6f);
    EXPECT_NEAR(hits[0].v, 0.5f, 1e-6f);
    EXPECT_NEAR(hits[0].t, 5.0f, 1e-6f);
}

TEST(Bvh, RayIntervalIsOpenBelowAndClosedAbove) {
    TriangleMesh one;
    one.positions = {{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}};
    one.triangles = {{0, 1, 2}};
    const Bvh bvh = build_bvh(one);
    const DeviceBvh device_bvh(test::shared_context(), bvh);
    DeviceTracer tracer(test::shared_context(), device_bvh);
    const auto hits = tracer.trace_closest({test::make_ray({0, 0, 0}, {0, 0, 1}, 0.0f, 3.0f),
                                            test::make_ray({0, 0, 0}, {0, 0, 1}, 3.0f, 5.0f),
                                            test::make_ray({0, 0, 0}, {0, 0, 1}, 0.0f, 2.99f)});
    EXPECT_EQ(hits[0].primitive, 0u);         // t = tmax counts
    EXPECT_EQ(hits[1].primitive, RC_NO_HIT);  // t = tmin does not
    EXPECT_EQ(hits[2].primitive, RC_NO_HIT);
}

}  // namespace
}  // namespace rc
