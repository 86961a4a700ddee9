// Ray sets for the traversal tests, drawn with the counter-based RNG (reproducible).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc::test {

struct Bounds {
    glm::vec3 lower;
    glm::vec3 upper;
};
Bounds mesh_bounds(const TriangleMesh& mesh);

shared::Ray make_ray(glm::vec3 origin, glm::vec3 direction, float tmin, float tmax);

// Origins uniform in `bounds` grown by `margin` of its diagonal, directions uniform on the
// sphere, tmin 0, tmax +inf.
std::vector<shared::Ray> random_rays(const Bounds& bounds, size_t count, uint32_t seed,
                                     float margin = 0.2f);

// Rays from random origins (as in random_rays) aimed exactly at mesh vertices, or at points on
// mesh edges (a random parameter along the edge): direction = target - origin, tmax +inf, so the
// target is at t = 1. A target is `crossing` when the surface around it is closed (every edge at
// it shared by exactly two triangles, matched by position) and the ray crosses it transversally
// (every triangle there faces the ray the same way, |cos| >= 0.05): such a ray must hit at the
// target or before it, whatever the rounding.
struct AimedRays {
    std::vector<shared::Ray> rays;
    std::vector<bool> crossing;
};
AimedRays vertex_aimed_rays(const TriangleMesh& mesh, const Bounds& bounds, size_t count,
                            uint32_t seed);
AimedRays edge_aimed_rays(const TriangleMesh& mesh, const Bounds& bounds, size_t count,
                          uint32_t seed);

// Segments from the given surface rays' origins to random points on random triangles,
// tmax = 0.999 of the way (shadow-ray like).
std::vector<shared::Ray> surface_segments(const TriangleMesh& mesh,
                                          const std::vector<shared::Ray>& surface_rays,
                                          uint32_t seed);

// Rays with NaN, infinite or otherwise untraceable components.
std::vector<shared::Ray> malformed_rays();

}  // namespace rc::test
