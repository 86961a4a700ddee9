// Device traversal against Embree's rtcIntersect1 / rtcOccluded1 on the same triangles, in
// every BVH layout.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "bvh/embree_scene.h"
#include "layout_params.h"
#include "ray_sets.h"
#include "reference_intersector.h"
#include "scene/generated_meshes.h"
#include "test_support.h"

namespace rc {
namespace {

struct Tracers {
    Tracers(const TriangleMesh& mesh, BvhLayout layout)
        : bvh(build_bvh(mesh, layout)),
          device_bvh(test::layout_context(layout), bvh),
          device(test::layout_context(layout), device_bvh),
          embree(mesh) {}
    Bvh bvh;
    DeviceBvh device_bvh;
    DeviceTracer device;
    EmbreeScene embree;
};

struct Agreement {
    size_t rays = 0;
    size_t embree_hits = 0;
    size_t closest_disagreements = 0;
    size_t closest_ties = 0;  // disagreements the double-precision referee calls rounding ties
    size_t any_disagreements = 0;
    size_t any_ties = 0;
};

std::string describe(const shared::Ray& ray) {
    char text[256];
    std::snprintf(text, sizeof text, "o (%.9g %.9g %.9g) d (%.9g %.9g %.9g) t (%.9g, %.9g]",
                  ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                  ray.direction.z, ray.origin.w, ray.direction.w);
    return text;
}

// Every ray: the device's answer against Embree's; where they differ, the device's answer must
// be one that single-precision rounding allows (tests/support/reference_intersector.h).
Agreement compare(Tracers& tracers, const TriangleMesh& mesh, const std::vector<shared::Ray>& rays,
                  const char* label) {
    const std::vector<shared::Hit> device_hits = tracers.device.trace_closest(rays);
    const std::vector<unsigned> device_occluded = tracers.device.trace_any(rays);
    Agreement result;
    result.rays = rays.size();
    for (size_t i = 0; i < rays.size(); ++i) {
        const shared::Hit embree_hit = tracers.embree.intersect(rays[i]);
        const bool embree_occluded = tracers.embree.occluded(rays[i]);
        result.embree_hits += embree_hit.primitive != RC_NO_HIT;
        if (!same_closest_hit(device_hits[i], embree_hit)) {
            ++result.closest_disagreements;
            if (test::closest_hit_is_valid(mesh, rays[i], device_hits[i].primitive)) {
                ++result.closest_ties;
            } else {
                ADD_FAILURE() << label << " ray " << i << " " << describe(rays[i])
                              << ": device hit " << device_hits[i].primitive << " at t "
                              << device_hits[i].t << ", Embree hit " << embree_hit.primitive
                              << " at t " << embree_hit.t;
            }
        }
        if ((device_occluded[i] != 0) != embree_occluded) {
            ++result.any_disagreements;
            if (test::any_hit_is_valid(mesh, rays[i], device_occluded[i] != 0)) {
                ++result.any_ties;
            } else {
                ADD_FAILURE() << label << " ray " << i << " " << describe(rays[i])
                              << ": device occluded " << device_occluded[i] << ", Embree "
                              << embree_occluded;
            }
        }
    }
    std::printf(
        "%-18s %6zu rays %6zu hits: closest %zu differ (%zu ties), any %zu differ (%zu ties)\n",
        label, result.rays, result.embree_hits, result.closest_disagreements, result.closest_ties,
        result.any_disagreements, result.any_ties);
    return result;
}

// A ray aimed at a closed, transversally crossed vertex or edge point hits at t <= 1 (the
// target) up to rounding: nothing slips through between the triangles there.
void expect_crossings_hit(Tracers& tracers, const test::AimedRays& aimed, const char* label) {
    const std::vector<shared::Hit> hits = tracers.device.trace_closest(aimed.rays);
    const std::vector<unsigned> occluded = tracers.device.trace_any(aimed.rays);
    size_t crossings = 0;
    size_t escapes = 0;
    for (size_t i = 0; i < aimed.rays.size(); ++i) {
        if (!aimed.crossing[i]) {
            continue;
        }
        ++crossings;
        if (hits[i].primitive == RC_NO_HIT || hits[i].t > 1.0f + 1e-4f || occluded[i] == 0) {
            if (++escapes <= 5) {
                ADD_FAILURE() << label << " ray " << i << " " << describe(aimed.rays[i])
                              << " slipped through: hit " << hits[i].primitive << " at t "
                              << hits[i].t << ", occluded " << occluded[i];
            }
        }
    }
    std::printf("%-18s %6zu rays cross a closed surface at the target: %zu escape\n", label,
                crossings, escapes);
    EXPECT_EQ(escapes, 0u) << label;
}

void check_scene(const TriangleMesh& mesh, uint32_t seed, BvhLayout layout) {
    Tracers tracers(mesh, layout);
    const test::Bounds bounds = test::mesh_bounds(mesh);
    const auto random = test::random_rays(bounds, 40000, seed);
    const auto surface = tracers.device.diffuse_bounce_rays(random, seed + 1);
    const auto segments = test::surface_segments(mesh, surface, seed + 2);
    const auto vertices = test::vertex_aimed_rays(mesh, bounds, 20000, seed + 3);
    const auto edges = test::edge_aimed_rays(mesh, bounds, 20000, seed + 4);
    size_t total = 0;
    for (const auto& [label, rays] :
         {std::pair{"random", &random}, std::pair{"from surfaces", &surface},
          std::pair{"surface segments", &segments}, std::pair{"aimed at vertices", &vertices.rays},
          std::pair{"aimed at edges", &edges.rays}}) {
        const Agreement agreement = compare(tracers, mesh, *rays, label);
        total += agreement.rays;
        EXPECT_EQ(agreement.closest_disagreements, agreement.closest_ties) << label;
        EXPECT_EQ(agreement.any_disagreements, agreement.any_ties) << label;
    }
    EXPECT_GE(total, 100000u);
    for (const auto& [label, aimed] :
         {std::pair{"aimed at vertices", &vertices}, std::pair{"aimed at edges", &edges}}) {
        expect_crossings_hit(tracers, *aimed, label);
    }
}

class EmbreeAgreement : public ::testing::TestWithParam<BvhLayout> {};

TEST_P(EmbreeAgreement, CornellBox) { check_scene(test::load_cornell_box().mesh, 11, GetParam()); }

TEST_P(EmbreeAgreement, RandomTriangleSoup) {
    check_scene(make_triangle_soup(20000, 7, glm::vec3(-1.0f), glm::vec3(1.0f), 0.3f), 21,
                GetParam());
}

TEST_P(EmbreeAgreement, DenseTessellatedSphere) {
    check_scene(make_icosphere(glm::vec3(0.5f, -2.0f, 3.0f), 2.0f, 6, 0.05f, 7.0f), 31, GetParam());
}

}  // namespace
}  // namespace rc

namespace rc {
namespace {

// NaN, infinite or otherwise untraceable rays: no crash, no hang, no hit. Embree is not asked:
// such rays violate its API contract (Debian's build aborts on the assertion ray.valid()).
TEST_P(EmbreeAgreement, MalformedRaysHitNothing) {
    const Scene scene = test::load_cornell_box();
    Tracers tracers(scene.mesh, GetParam());
    const std::vector<shared::Ray> rays = test::malformed_rays();
    const std::vector<shared::Hit> hits = tracers.device.trace_closest(rays);
    const std::vector<unsigned> occluded = tracers.device.trace_any(rays);
    for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(hits[i].primitive, RC_NO_HIT) << describe(rays[i]);
        EXPECT_EQ(occluded[i], 0u) << describe(rays[i]);
    }
}

INSTANTIATE_TEST_SUITE_P(Layouts, EmbreeAgreement, test::kAllBvhLayouts,
                         test::bvh_layout_test_name);

}  // namespace
}  // namespace rc
