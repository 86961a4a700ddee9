// A double-precision brute-force ray/triangle referee with explicit float tolerances. It judges
// the rays on which the device and Embree disagree: a disagreement is a tie (acceptable) only
// when the exact answer lies within single-precision rounding of an edge or of the ends of the
// ray interval, and the device's answer is one of the answers rounding allows.
#pragma once

#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc::test {

struct ReferenceHit {
    double t = 0.0;
    bool possible = false;  // a hit within float tolerance of the exact geometry
    bool certain = false;   // a hit by more than the tolerance (inside, within the interval)
    double tolerance_t = 0.0;
};

// The exact (double) intersection of the ray with one triangle, with tolerances derived from the
// coordinates' magnitude and the ray's angle to the triangle (grazing rays get wider tolerances).
ReferenceHit reference_intersect(const TriangleMesh& mesh, size_t triangle, const shared::Ray& ray);

// Whether the device's closest-hit answer (primitive, or RC_NO_HIT) is one that rounding
// allows: a possible hit with no certain hit clearly nearer, or a miss with no certain hit.
bool closest_hit_is_valid(const TriangleMesh& mesh, const shared::Ray& ray, unsigned primitive);

// Whether an any-hit answer is one rounding allows: occluded needs a possible hit, not
// occluded needs no certain hit.
bool any_hit_is_valid(const TriangleMesh& mesh, const shared::Ray& ray, bool occluded);

}  // namespace rc::test
