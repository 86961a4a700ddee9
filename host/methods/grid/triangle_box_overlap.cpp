#include "methods/grid/triangle_box_overlap.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rc {
namespace {

// Whether the triangle's vertices (relative to the box's centre) and the box of half-sizes h,
// projected on `axis`, leave a gap (Akenine-Möller 2001, §3: p_i = axis . v_i, r = sum h_k |a_k|).
bool separated_on(const glm::dvec3& axis, const glm::dvec3 v[3], const glm::dvec3& h) {
    const double p0 = glm::dot(axis, v[0]);
    const double p1 = glm::dot(axis, v[1]);
    const double p2 = glm::dot(axis, v[2]);
    const double r = h.x * std::fabs(axis.x) + h.y * std::fabs(axis.y) + h.z * std::fabs(axis.z);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

}  // namespace

bool triangle_overlaps_box(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                           const glm::dvec3& lower, const glm::dvec3& upper) {
    const glm::dvec3 centre = 0.5 * (lower + upper);
    const glm::dvec3 h = 0.5 * (upper - lower);
    const glm::dvec3 v[3] = {a - centre, b - centre, c - centre};
    // Step 1: the box's face normals (the triangle's bounding box against the box).
    for (int k = 0; k < 3; ++k) {
        if (std::min({v[0][k], v[1][k], v[2][k]}) > h[k] ||
            std::max({v[0][k], v[1][k], v[2][k]}) < -h[k]) {
            return false;
        }
    }
    const glm::dvec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    // Step 2: the triangle's normal (the plane against the box).
    if (separated_on(glm::cross(edges[0], edges[1]), v, h)) {
        return false;
    }
    // Step 3: the nine cross products of a box axis and a triangle edge.
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 axis(0.0);
        axis[k] = 1.0;
        for (const glm::dvec3& edge : edges) {
            if (separated_on(glm::cross(axis, edge), v, h)) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace rc
