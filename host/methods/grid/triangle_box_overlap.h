// Whether a triangle and an axis-aligned box share a point: the separating-axis test of
// Akenine-Möller ("Fast 3D Triangle-Box Overlap Testing", Journal of Graphics Tools 6(1), 2001),
// in double precision.
#pragma once

#include <glm/vec3.hpp>

namespace rc {

// Closed triangle (a, b, c) against the closed box [lower, upper].
bool triangle_overlaps_box(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                           const glm::dvec3& lower, const glm::dvec3& upper);

}  // namespace rc
