// The flattened BVHs of both layouts (docs/bvh.md): every triangle in exactly one leaf, bounds
// that contain what they bound (the wide layout's quantised boxes decoded exactly), the depth
// bound the traversal stacks rely on, and tiny trees.
#include "bvh/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <set>

#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "layout_params.h"
#include "ray_sets.h"
#include "scene/generated_meshes.h"
#include "test_support.h"
#include "util/error.h"

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

void check_bvh4(const Bvh& bvh) {
    std::vector<int> seen(bvh.triangles.size(), 0);
    unsigned max_depth = 0;
    check_subtree(bvh, 0, 1, seen, max_depth);
    for (size_t i = 0; i < seen.size(); ++i) {
        ASSERT_EQ(seen[i], 1) << "leaf-order triangle " << i;
    }
    EXPECT_EQ(max_depth, bvh.depth);
}

// A wide node's child box as the traversal decodes it: planes origin + q 2^(exponent - 127) in
// float (q 2^e is exact, so this is one rounding).
struct DecodedBox {
    float lower[3];
    float upper[3];
};

DecodedBox decoded_box(const shared::WideBvhNode& node, int slot) {
    const float origin[3] = {node.origin_x, node.origin_y, node.origin_z};
    const shared::uchar exponent[3] = {node.exponent_x, node.exponent_y, node.exponent_z};
    const shared::uchar* lower[3] = {node.lower_x, node.lower_y, node.lower_z};
    const shared::uchar* upper[3] = {node.upper_x, node.upper_y, node.upper_z};
    DecodedBox box;
    for (int k = 0; k < 3; ++k) {
        const float scale = std::ldexp(1.0f, static_cast<int>(exponent[k]) - 127);
        box.lower[k] = origin[k] + static_cast<float>(lower[k][slot]) * scale;
        box.upper[k] = origin[k] + static_cast<float>(upper[k][slot]) * scale;
    }
    return box;
}

bool holds_triangle(const DecodedBox& box, const TriangleMesh& mesh, unsigned primitive) {
    for (unsigned corner = 0; corner < 3; ++corner) {
        const glm::vec3& p = mesh.positions[mesh.triangles[primitive][corner]];
        for (int k = 0; k < 3; ++k) {
            if (p[k] < box.lower[k] || p[k] > box.upper[k]) {
                return false;
            }
        }
    }
    return true;
}

// Walks the wide tree: inner children first, then leaves, then unused slots; every primitive
// of a subtree inside each box above it. Returns the subtree's primitives.
std::vector<unsigned> check_wide_subtree(const Bvh& bvh, const TriangleMesh& mesh,
                                         uint32_t node_index, unsigned depth, unsigned& max_depth) {
    max_depth = std::max(max_depth, depth);
    const shared::WideBvhNode& node = bvh.wide_nodes.at(node_index);
    std::vector<unsigned> primitives;
    const unsigned inner_count = static_cast<unsigned>(std::popcount(node.inner_mask));
    EXPECT_EQ(node.inner_mask, (1u << inner_count) - 1u) << "inner children come first";
    bool unused_seen = false;
    for (unsigned slot = 0; slot < RC_WIDE_BVH_WIDTH; ++slot) {
        std::vector<unsigned> child;
        if (slot < inner_count) {
            const uint32_t child_index = node.child_base + slot;
            EXPECT_GT(child_index, node_index) << "children follow their parent";
            child = check_wide_subtree(bvh, mesh, child_index, depth + 1, max_depth);
        } else if (node.meta[slot] != 0) {
            EXPECT_FALSE(unused_seen) << "leaves come before unused slots";
            const unsigned packets = node.meta[slot] >> 5u;
            EXPECT_GE(packets, 1u);
            EXPECT_LE(packets * 4u, static_cast<unsigned>(RC_WIDE_BVH_MAX_LEAF_SIZE));
            const size_t first =
                node.packet_base + (node.meta[slot] & 31u) - bvh.wide_packet_offset();
            std::set<unsigned> leaf;
            for (size_t i = first; i < first + packets; ++i) {
                const shared::TrianglePacket& packet = bvh.packets.at(i);
                for (int lane = 0; lane < 4; ++lane) {
                    const unsigned p = (&packet.primitive.x)[lane];
                    const glm::uvec3& t = mesh.triangles.at(p);
                    for (int k = 0; k < 3; ++k) {
                        EXPECT_EQ((&packet.v0[k].x)[lane], mesh.positions[t.x][k]);
                        EXPECT_EQ((&packet.v1[k].x)[lane], mesh.positions[t.y][k]);
                        EXPECT_EQ((&packet.v2[k].x)[lane], mesh.positions[t.z][k]);
                    }
                    leaf.insert(p);
                }
            }
            child.assign(leaf.begin(), leaf.end());
        } else {
            unused_seen = true;
            EXPECT_EQ(node.lower_x[slot], 255);
            EXPECT_EQ(node.upper_x[slot], 0);
            continue;
        }
        const DecodedBox box = decoded_box(node, static_cast<int>(slot));
        for (unsigned p : child) {
            EXPECT_TRUE(holds_triangle(box, mesh, p)) << "primitive " << p;
        }
        primitives.insert(primitives.end(), child.begin(), child.end());
    }
    return primitives;
}

void check_wide(const Bvh& bvh, const TriangleMesh& mesh) {
    unsigned max_depth = 0;
    std::vector<unsigned> primitives = check_wide_subtree(bvh, mesh, 0, 1, max_depth);
    std::sort(primitives.begin(), primitives.end());
    ASSERT_EQ(primitives.size(), mesh.triangles.size()) << "every primitive in exactly one leaf";
    for (size_t p = 0; p < primitives.size(); ++p) {
        ASSERT_EQ(primitives[p], p);
    }
    EXPECT_EQ(max_depth, bvh.depth);
}

void check_structure(const TriangleMesh& mesh, BvhLayout layout) {
    const Bvh bvh = build_bvh(mesh, layout);
    ASSERT_EQ(bvh.layout, layout);
    ASSERT_EQ(bvh.triangles.size(), mesh.triangles.size());
    if (layout == BvhLayout::kWide) {
        check_wide(bvh, mesh);
    } else {
        check_bvh4(bvh);
    }
    EXPECT_LE(bvh.depth, static_cast<unsigned>(RC_BVH_MAX_DEPTH));
    // The primitive map inverts the leaf order, and leaf triangles are the mesh's triangles.
    for (size_t p = 0; p < mesh.triangles.size(); ++p) {
        const shared::Triangle& t = bvh.triangles[bvh.triangle_of_primitive[p]];
        ASSERT_EQ(shared::rc_as_uint(t.v0.w), p);
        EXPECT_EQ(t.v1.x, mesh.positions[mesh.triangles[p].y].x);
        EXPECT_EQ(t.v2.z, mesh.positions[mesh.triangles[p].z].z);
    }
}

class Bvh : public ::testing::TestWithParam<BvhLayout> {
   protected:
    Context& context() { return test::layout_context(GetParam()); }
};

TEST_P(Bvh, CornellBoxStructure) { check_structure(test::load_cornell_box().mesh, GetParam()); }

TEST_P(Bvh, TriangleSoupStructure) {
    check_structure(make_triangle_soup(5000, 3, glm::vec3(-1.0f), glm::vec3(1.0f), 0.2f),
                    GetParam());
}

TEST_P(Bvh, SphereFarFromTheOriginStructure) {
    // Small boxes far from the origin: the quantisation grids' planes round.
    check_structure(make_icosphere(glm::vec3(3000.0f, -2000.0f, 1500.0f), 0.5f, 4), GetParam());
}

TEST_P(Bvh, IdenticalTrianglesStayWithinTheDepthBound) {
    // 2000 copies of one triangle: no split separates them.
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles.assign(2000, glm::uvec3(0, 1, 2));
    check_structure(mesh, GetParam());
}

TEST_P(Bvh, SingleTriangleAndEmptyMeshesTrace) {
    TriangleMesh one;
    one.positions = {{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}};
    one.triangles = {{0, 1, 2}};
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<shared::Ray> rays = {test::make_ray({0, 0, 0}, {0, 0, 1}, 0, inf),
                                           test::make_ray({0, 0, 0}, {0, 0, -1}, 0, inf)};
    {
        const rc::Bvh bvh = build_bvh(one, GetParam());
        const DeviceBvh device_bvh(context(), bvh);
        DeviceTracer tracer(context(), device_bvh);
        const auto hits = tracer.trace_closest(rays);
        EXPECT_EQ(hits[0].primitive, 0u);
        EXPECT_FLOAT_EQ(hits[0].t, 2.0f);
        EXPECT_EQ(hits[1].primitive, RC_NO_HIT);
        const auto occluded = tracer.trace_any(rays);
        EXPECT_EQ(occluded[0], 1u);
        EXPECT_EQ(occluded[1], 0u);
    }
    {
        const rc::Bvh bvh = build_bvh(TriangleMesh{}, GetParam());
        const DeviceBvh device_bvh(context(), bvh);
        DeviceTracer tracer(context(), device_bvh);
        EXPECT_EQ(tracer.trace_closest(rays)[0].primitive, RC_NO_HIT);
        EXPECT_EQ(tracer.trace_any(rays)[0], 0u);
    }
}

TEST_P(Bvh, BarycentricsLocateTheHitPoint) {
    TriangleMesh one;
    one.positions = {{0, 0, 5}, {4, 0, 5}, {0, 2, 5}};
    one.triangles = {{0, 1, 2}};
    const rc::Bvh bvh = build_bvh(one, GetParam());
    const DeviceBvh device_bvh(context(), bvh);
    DeviceTracer tracer(context(), device_bvh);
    // Aim at 0.25 v1 + 0.5 v2 + 0.25 v0 = (1, 1, 5).
    const auto hits = tracer.trace_closest(
        {test::make_ray({1, 1, 0}, {0, 0, 1}, 0, std::numeric_limits<float>::infinity())});
    EXPECT_EQ(hits[0].primitive, 0u);
    EXPECT_NEAR(hits[0].u, 0.25f, 1e-6f);
    EXPECT_NEAR(hits[0].v, 0.5f, 1e-6f);
    EXPECT_NEAR(hits[0].t, 5.0f, 1e-6f);
}

TEST_P(Bvh, RayIntervalIsOpenBelowAndClosedAbove) {
    TriangleMesh one;
    one.positions = {{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}};
    one.triangles = {{0, 1, 2}};
    const rc::Bvh bvh = build_bvh(one, GetParam());
    const DeviceBvh device_bvh(context(), bvh);
    DeviceTracer tracer(context(), device_bvh);
    const auto hits = tracer.trace_closest({test::make_ray({0, 0, 0}, {0, 0, 1}, 0.0f, 3.0f),
                                            test::make_ray({0, 0, 0}, {0, 0, 1}, 3.0f, 5.0f),
                                            test::make_ray({0, 0, 0}, {0, 0, 1}, 0.0f, 2.99f)});
    EXPECT_EQ(hits[0].primitive, 0u);         // t = tmax counts
    EXPECT_EQ(hits[1].primitive, RC_NO_HIT);  // t = tmin does not
    EXPECT_EQ(hits[2].primitive, RC_NO_HIT);
}

TEST_P(Bvh, DeviceRefusesABvhOfTheOtherLayout) {
    TriangleMesh one;
    one.positions = {{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}};
    one.triangles = {{0, 1, 2}};
    const BvhLayout other = GetParam() == BvhLayout::kWide ? BvhLayout::kBvh4 : BvhLayout::kWide;
    const rc::Bvh bvh = build_bvh(one, other);
    EXPECT_THROW(DeviceBvh(context(), bvh), Error);
}

INSTANTIATE_TEST_SUITE_P(Layouts, Bvh, test::kAllBvhLayouts, test::bvh_layout_test_name);

}  // namespace
}  // namespace rc
