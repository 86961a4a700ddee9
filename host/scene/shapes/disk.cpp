#include "scene/shapes/disk.h"

#include <cmath>

#include "scene/shapes/tessellation.h"

namespace rc {

TriangleMesh make_disk(const DiskShape& disk) {
    TriangleMesh mesh;
    const int segments = arc_segments(disk.phi_max_degrees);
    const double phi_max = disk.phi_max_degrees * (3.14159265358979323846 / 180.0);
    // A full disk's last column repeats its first bit for bit, so the seam has no crack.
    const bool full = disk.phi_max_degrees >= 360.0f;
    const bool centred = disk.inner_radius == 0.0f;
    for (int j = 0; j <= segments; ++j) {
        const int column = full && j == segments ? 0 : j;
        const double phi = phi_max * column / segments;
        const float c = static_cast<float>(std::cos(phi));
        const float s = static_cast<float>(std::sin(phi));
        const float u = static_cast<float>(j) / static_cast<float>(segments);
        mesh.positions.emplace_back(disk.radius * c, disk.radius * s, disk.height);
        mesh.uvs.emplace_back(u, 0.0f);
        // The inner rim (one vertex at the centre when there is no hole).
        mesh.positions.emplace_back(disk.inner_radius * c, disk.inner_radius * s, disk.height);
        mesh.uvs.emplace_back(u, 1.0f);
    }
    for (int j = 0; j < segments; ++j) {
        const auto outer0 = static_cast<unsigned>(2 * j);
        const auto inner0 = outer0 + 1;
        const auto outer1 = outer0 + 2;
        const auto inner1 = outer0 + 3;
        // Counter-clockwise seen from +z: outward rim first, then increasing phi.
        mesh.triangles.push_back({inner0, outer0, outer1});
        if (!centred) {
            mesh.triangles.push_back({inner0, outer1, inner1});
        }
    }
    return mesh;
}

}  // namespace rc
