// Watertightness: rays from inside closed meshes, aimed exactly at every vertex and at points on
// every edge, never escape between the triangles (Woop et al. 2013 promise this; fused
// multiply-adds in the edge functions, for one, break it).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <limits>
#include <set>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "layout_params.h"
#include "ray_sets.h"
#include "scene/generated_meshes.h"
#include "test_support.h"

namespace rc {
namespace {

// Rays from `inside` to every vertex and to the points at 1/4, 1/2 (and a random-ish 0.618) of
// every edge.
std::vector<shared::Ray> rays_through_vertices_and_edges(const TriangleMesh& mesh,
                                                         glm::vec3 inside) {
    std::vector<shared::Ray> rays;
    const float inf = std::numeric_limits<float>::infinity();
    for (const glm::vec3& p : mesh.positions) {
        rays.push_back(test::make_ray(inside, p - inside, 0.0f, inf));
    }
    std::set<std::pair<unsigned, unsigned>> edges;
    for (const glm::uvec3& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
        }
    }
    for (const auto& [a, b] : edges) {
        for (float s : {0.25f, 0.5f, 0.6180339887f}) {
            const glm::vec3 target =
                mesh.positions[a] + s * (mesh.positions[b] - mesh.positions[a]);
            rays.push_back(test::make_ray(inside, target - inside, 0.0f, inf));
        }
    }
    return rays;
}

size_t count_escapes(const TriangleMesh& mesh, const std::vector<shared::Ray>& rays,
                     BvhLayout layout) {
    const Bvh bvh = build_bvh(mesh, layout);
    const DeviceBvh device_bvh(test::layout_context(layout), bvh);
    DeviceTracer tracer(test::layout_context(layout), device_bvh);
    const std::vector<shared::Hit> hits = tracer.trace_closest(rays);
    const std::vector<unsigned> occluded = tracer.trace_any(rays);
    size_t escapes = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const bool escaped = hits[i].primitive == RC_NO_HIT || occluded[i] == 0;
        escapes += escaped ? 1 : 0;
    }
    return escapes;
}

class Watertight : public ::testing::TestWithParam<BvhLayout> {};

TEST_P(Watertight, SphereFromItsCentre) {
    const glm::vec3 centre(0.25f, -0.5f, 0.75f);
    const TriangleMesh mesh = make_icosphere(centre, 1.0f, 5);
    const auto rays = rays_through_vertices_and_edges(mesh, centre);
    EXPECT_GT(rays.size(), 100000u);
    EXPECT_EQ(count_escapes(mesh, rays, GetParam()), 0u);
}

TEST_P(Watertight, BumpySphereFarFromTheOriginFromOffCentre) {
    // Coordinates near 3000 leave few mantissa bits for the edge functions.
    const glm::vec3 centre(3000.0f, -2000.0f, 1500.0f);
    const TriangleMesh mesh = make_icosphere(centre, 5.0f, 5, 0.1f, 11.0f);
    const auto rays = rays_through_vertices_and_edges(mesh, centre + glm::vec3(0.7f, -1.1f, 0.3f));
    EXPECT_EQ(count_escapes(mesh, rays, GetParam()), 0u);
}

TEST_P(Watertight, CornellBoxClosedByAFrontWall) {
    // The box is open at the front: close it with a quad over the opening, then every ray from
    // inside must stay inside.
    TriangleMesh mesh = test::load_cornell_box().mesh;
    const TriangleMesh front = [] {
        TriangleMesh quad;
        quad.positions = {
            {552.8f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 548.8f, 0.0f}, {556.0f, 548.8f, 0.0f}};
        quad.triangles = {{0, 1, 2}, {0, 2, 3}};
        return quad;
    }();
    mesh.append(front);
    // From a point above the blocks, every vertex and edge of the closed room is a target; the
    // block vertices occlude some targets, which only moves the hit nearer.
    const auto rays = rays_through_vertices_and_edges(mesh, glm::vec3(278.0f, 450.0f, 280.0f));
    EXPECT_EQ(count_escapes(mesh, rays, GetParam()), 0u);
}

INSTANTIATE_TEST_SUITE_P(Layouts, Watertight, test::kAllBvhLayouts, test::bvh_layout_test_name);

}  // namespace
}  // namespace rc
