#include "reference_intersector.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace rc::test {
namespace {

// Positional uncertainty of a single-precision hit point, in units of the largest coordinate
// magnitude involved: a generous 16 ulps.
constexpr double kUlps = 16.0 * 5.9604644775390625e-8;

double max_abs(const glm::dvec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

}  // namespace

ReferenceHit reference_intersect(const TriangleMesh& mesh, size_t triangle,
                                 const shared::Ray& ray) {
    const glm::uvec3& index = mesh.triangles[triangle];
    const glm::dvec3 v0(mesh.positions[index.x]);
    const glm::dvec3 v1(mesh.positions[index.y]);
    const glm::dvec3 v2(mesh.positions[index.z]);
    const glm::dvec3 o(ray.origin.x, ray.origin.y, ray.origin.z);
    const glm::dvec3 d(ray.direction.x, ray.direction.y, ray.direction.z);
    const double tmin = ray.origin.w;
    const double tmax = ray.direction.w;

    ReferenceHit hit;
    const glm::dvec3 e1 = v1 - v0;
    const glm::dvec3 e2 = v2 - v0;
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double twice_area = glm::length(normal);
    const double length_d = glm::length(d);
    if (twice_area == 0.0 || length_d == 0.0) {
        return hit;
    }
    const double cosine = std::fabs(glm::dot(normal, d)) / (twice_area * length_d);
    const double scale = std::max({max_abs(o), max_abs(v0), max_abs(v1), max_abs(v2)});
    const double position_tolerance = kUlps * scale / std::max(cosine, 1e-9);
    hit.tolerance_t = position_tolerance / length_d;

    // Möller-Trumbore in double precision.
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) {
        // Parallel to the plane: rounding may still report an edge-on hit.
        hit.possible = true;
        hit.t = 0.0;
        return hit;
    }
    const glm::dvec3 s = o - v0;
    const double u = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    hit.t = glm::dot(e2, q) / det;
    const double b[3] = {1.0 - u - v, u, v};
    // Distance of each vertex to its opposite edge: barycentric tolerance = position / height.
    const double heights[3] = {twice_area / glm::length(v2 - v1), twice_area / glm::length(e2),
                               twice_area / glm::length(e1)};
    bool inside_possible = true;
    bool inside_certain = true;
    for (int k = 0; k < 3; ++k) {
        const double tolerance = position_tolerance / heights[k];
        inside_possible = inside_possible && b[k] >= -tolerance;
        inside_certain = inside_certain && b[k] >= tolerance;
    }
    hit.possible =
        inside_possible && hit.t >= tmin - hit.tolerance_t && hit.t <= tmax + hit.tolerance_t;
    hit.certain =
        inside_certain && hit.t > tmin + hit.tolerance_t && hit.t < tmax - hit.tolerance_t;
    return hit;
}

bool closest_hit_is_valid(const TriangleMesh& mesh, const shared::Ray& ray, unsigned primitive) {
    ReferenceHit chosen;
    if (primitive != RC_NO_HIT) {
        chosen = reference_intersect(mesh, primitive, ray);
        if (!chosen.possible) {
            return false;
        }
    }
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        if (i == primitive) {
            continue;
        }
        const ReferenceHit other = reference_intersect(mesh, i, ray);
        if (!other.certain) {
            continue;
        }
        if (primitive == RC_NO_HIT) {
            return false;  // missed a certain hit
        }
        if (other.t < chosen.t - chosen.tolerance_t - other.tolerance_t) {
            return false;  // a certain hit clearly nearer than the one reported
        }
    }
    return true;
}

bool any_hit_is_valid(const TriangleMesh& mesh, const shared::Ray& ray, bool occluded) {
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const ReferenceHit hit = reference_intersect(mesh, i, ray);
        if (occluded && hit.possible) {
            return true;
        }
        if (!occluded && hit.certain) {
            return false;
        }
    }
    return !occluded;
}

}  // namespace rc::test
