// The double-precision referee of the Embree agreement tests can fail: it rejects answers that
// are wrong by more than rounding.
#include "reference_intersector.h"

#include <gtest/gtest.h>

#include "bvh/embree_scene.h"
#include "ray_sets.h"
#include "test_support.h"

namespace rc {
namespace {

TEST(ReferenceIntersector, AcceptsEmbreeAndRejectsWrongAnswers) {
    const TriangleMesh mesh = test::load_cornell_box().mesh;
    const EmbreeScene embree(mesh);
    const auto rays = test::random_rays(test::mesh_bounds(mesh), 2000, 77);
    size_t hits = 0;
    size_t accepted_embree = 0;
    size_t rejected_misses = 0;
    size_t rejected_others = 0;
    for (const shared::Ray& ray : rays) {
        const shared::Hit hit = embree.intersect(ray);
        accepted_embree += test::closest_hit_is_valid(mesh, ray, hit.primitive);
        if (hit.primitive == RC_NO_HIT) {
            continue;
        }
        ++hits;
        rejected_misses += !test::closest_hit_is_valid(mesh, ray, RC_NO_HIT);
        // Any other triangle, claimed as the closest hit.
        const unsigned other = (hit.primitive + 7) % static_cast<unsigned>(mesh.triangles.size());
        rejected_others += !test::closest_hit_is_valid(mesh, ray, other);
        EXPECT_TRUE(test::any_hit_is_valid(mesh, ray, true));
    }
    EXPECT_EQ(accepted_embree, rays.size());
    EXPECT_GT(hits, 500u);
    // Nearly every hit is far from edges and interval ends: claiming a miss is wrong.
    EXPECT_GT(rejected_misses, hits * 99 / 100);
    EXPECT_GT(rejected_others, hits * 9 / 10);
}

}  // namespace
}  // namespace rc
