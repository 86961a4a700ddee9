// pbrt-v4's loopsubdiv shape (Physically Based Rendering, 3rd ed., §3.8; Loop, "Smooth Subdivision
// Surfaces Based on Triangles", 1987): a triangle control mesh refined `levels` times by Loop's
// rules, its vertices then moved to the limit surface with the limit surface's normals. The
// refinement and limit evaluation are OpenSubdiv's (Far::TopologyRefiner, Sdc::SCHEME_LOOP,
// boundaries interpolated edge-only: Loop's boundary rules, as pbrt's).
#pragma once

#include <cstddef>

#include "scene/triangle_mesh.h"

namespace rc {

// The most triangles a subdivided shape may have (the instancing bound of the pbrt import).
inline constexpr size_t kMaxSubdividedTriangles = size_t{1} << 24;

// The limit mesh of `control` (its positions and triangles; normals, uvs and materials are not
// read) after `levels` refinements (0 moves the control vertices to the limit surface). Throws
// Error when the result would exceed kMaxSubdividedTriangles.
TriangleMesh make_loop_subdivision(const TriangleMesh& control, int levels);

}  // namespace rc
