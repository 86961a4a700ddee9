// pbrt-v4's cylinder (Physically Based Rendering, 4th ed., §6.3): radius r about the z axis,
// zmin <= z <= zmax, 0 <= phi <= phimax, open at both ends, its surface normal pointing away from
// the axis; as triangles with smooth normals.
#pragma once

#include "scene/triangle_mesh.h"

namespace rc {

struct CylinderShape {
    float radius = 1.0f;
    float z_min = -1.0f;
    float z_max = 1.0f;
    float phi_max_degrees = 360.0f;
};

// The cylinder tessellated around (scene/shapes/tessellation.h; one band along z, which is
// exact), wound counter-clockwise seen from outside, vertex normals (cos phi, sin phi, 0) and
// pbrt's (u, v) = (phi / phimax, (z - zmin) / (zmax - zmin)). The parameters must be valid:
// radius > 0, zmin < zmax, phimax in (0, 360].
TriangleMesh make_cylinder(const CylinderShape& cylinder);

}  // namespace rc
