// Secondary-ray origins (Wächter and Binder, Ray Tracing Gems ch. 6): a ray leaving a surface
// from its offset origin never hits that surface again, at any scale or distance from the
// origin, while rays started at the raw hit point do.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "ray_sets.h"
#include "scene/generated_meshes.h"
#include "test_support.h"

namespace rc {
namespace {

// A tilted quad (two triangles) of size `size` centred at `centre`, and rays from above that hit
// it, at angles down to grazing, within `spread` * size of the centre.
struct Setup {
    TriangleMesh mesh;
    std::vector<shared::Ray> primary;
};

Setup tilted_quad(glm::vec3 centre, float size, float spread) {
    Setup setup;
    const glm::vec3 e1 = glm::normalize(glm::vec3(1.0f, 0.3f, 0.1f)) * size;
    const glm::vec3 e2 = glm::normalize(glm::cross(glm::vec3(0.2f, 0.1f, 1.0f), e1)) * size;
    setup.mesh = make_quad(centre - 0.5f * (e1 + e2), e1, e2);
    const glm::vec3 normal = glm::normalize(glm::cross(e1, e2));
    const float reach = size * spread;
    const std::vector<shared::Ray> random =
        test::random_rays({centre - glm::vec3(reach), centre + glm::vec3(reach)}, 20000, 5, 0.0f);
    for (const shared::Ray& r : random) {
        // Origins above the plane, aimed at random points of the quad near its centre.
        glm::vec3 o(r.origin.x, r.origin.y, r.origin.z);
        o += normal * (0.03f * reach + std::fabs(glm::dot(o - centre, normal)));
        const glm::vec3 target =
            centre + (spread * 1.3f) * (r.direction.x * e1 + r.direction.y * e2);
        setup.primary.push_back(
            test::make_ray(o, target - o, 0.0f, std::numeric_limits<float>::infinity()));
    }
    return setup;
}

struct SelfHits {
    size_t offset = 0;  // bounce rays from the offset origin that hit the quad again
    size_t raw = 0;     // the same directions from the raw hit point
    size_t rays = 0;
};

SelfHits count_self_hits(const Setup& setup) {
    const Bvh bvh = build_bvh(setup.mesh, test::shared_context().bvh_layout());
    const DeviceBvh device_bvh(test::shared_context(), bvh);
    DeviceTracer tracer(test::shared_context(), device_bvh);
    const std::vector<shared::Hit> hits = tracer.trace_closest(setup.primary);
    const std::vector<shared::Ray> bounces =
        tracer.diffuse_bounce_rays(setup.primary, 99, /*traceable_only=*/false);
    std::vector<shared::Ray> offset;
    std::vector<shared::Ray> raw;
    for (size_t i = 0; i < bounces.size(); ++i) {
        if (hits[i].primitive == RC_NO_HIT) {
            continue;
        }
        offset.push_back(bounces[i]);
        // The raw hit point o + t d in single precision.
        const shared::Ray& p = setup.primary[i];
        shared::Ray r = bounces[i];
        r.origin = {p.origin.x + hits[i].t * p.direction.x, p.origin.y + hits[i].t * p.direction.y,
                    p.origin.z + hits[i].t * p.direction.z, 0.0f};
        raw.push_back(r);
    }
    SelfHits result;
    result.rays = offset.size();
    for (const shared::Hit& h : tracer.trace_closest(offset)) {
        result.offset += h.primitive != RC_NO_HIT;
    }
    for (const shared::Hit& h : tracer.trace_closest(raw)) {
        result.raw += h.primitive != RC_NO_HIT;
    }
    return result;
}

TEST(RayOffset, BouncesNeverHitTheSurfaceTheyLeaveAtAnyScale) {
    size_t raw_total = 0;
    struct Case {
        glm::vec3 centre;
        float size;
        float spread;
    };
    for (const Case& c :
         {Case{glm::vec3(0.0f), 1.0f, 0.3f}, Case{glm::vec3(0.01f, -0.02f, 0.0f), 0.05f, 0.3f},
          Case{glm::vec3(1000.0f, 2000.0f, -500.0f), 300.0f, 0.3f},
          Case{glm::vec3(-6.0e4f, 1.0e4f, 3.0e4f), 50.0f, 0.3f},
          Case{glm::vec3(278.0f, 0.0f, 280.0f), 550.0f, 0.3f},
          // Hit points near the origin on a huge quad: the intersection error
          // follows the vertices' magnitude, not the hit point's.
          Case{glm::vec3(0.0f), 2000.0f, 0.001f},
          // Scenes scaled far down: the near-origin step is a fraction of the triangle's unit
          // (kernels/common/ray_offset.h), small enough to stay on the surface's side, large
          // enough to leave it.
          Case{glm::vec3(0.0f), 1e-6f, 0.3f}, Case{glm::vec3(3e-9f, -1e-9f, 2e-9f), 4e-9f, 0.3f}}) {
        const SelfHits hits = count_self_hits(tilted_quad(c.centre, c.size, c.spread));
        EXPECT_GT(hits.rays, 10000u);
        EXPECT_EQ(hits.offset, 0u) << "centre " << c.centre.x << " size " << c.size;
        raw_total += hits.raw;
        std::printf("size %g: %zu rays, %zu self-hits from offset origins, %zu from raw points\n",
                    c.size, hits.rays, hits.offset, hits.raw);
    }
    // Without the offset, rounding puts many raw origins below the surface: the test can tell.
    EXPECT_GT(raw_total, 100u);
}

}  // namespace
}  // namespace rc
