// pbrt-v4's disk (Physically Based Rendering, 4th ed., §6.5): the annulus innerradius <= r <=
// radius, 0 <= phi <= phimax, in the plane z = height, its surface normal +z; as triangles.
#pragma once

#include "scene/triangle_mesh.h"

namespace rc {

struct DiskShape {
    float height = 0.0f;
    float radius = 1.0f;
    float inner_radius = 0.0f;
    float phi_max_degrees = 360.0f;
};

// The disk tessellated (scene/shapes/tessellation.h), wound counter-clockwise seen from +z (its
// emitting side as an area light), with pbrt's (u, v) = (phi / phimax, (radius - r) / (radius -
// innerradius)). The parameters must be valid: 0 <= inner < radius, phimax in (0, 360].
TriangleMesh make_disk(const DiskShape& disk);

}  // namespace rc
