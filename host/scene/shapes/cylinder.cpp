#include "scene/shapes/cylinder.h"

#include <cmath>

#include "scene/shapes/tessellation.h"

namespace rc {

TriangleMesh make_cylinder(const CylinderShape& cylinder) {
    TriangleMesh mesh;
    const int segments = arc_segments(cylinder.phi_max_degrees);
    const double phi_max = cylinder.phi_max_degrees * (3.14159265358979323846 / 180.0);
    // A full cylinder's last column repeats its first bit for bit, so the seam has no crack.
    const bool full = cylinder.phi_max_degrees >= 360.0f;
    for (int j = 0; j <= segments; ++j) {
        const int column = full && j == segments ? 0 : j;
        const double phi = phi_max * column / segments;
        const glm::vec3 n(static_cast<float>(std::cos(phi)), static_cast<float>(std::sin(phi)),
                          0.0f);
        const float u = static_cast<float>(j) / static_cast<float>(segments);
        const glm::vec3 rim = cylinder.radius * n;
        mesh.positions.emplace_back(rim.x, rim.y, cylinder.z_min);
        mesh.normals.push_back(n);
        mesh.uvs.emplace_back(u, 0.0f);
        mesh.positions.emplace_back(rim.x, rim.y, cylinder.z_max);
        mesh.normals.push_back(n);
        mesh.uvs.emplace_back(u, 1.0f);
    }
    for (int j = 0; j < segments; ++j) {
        const auto low0 = static_cast<unsigned>(2 * j);
        const auto high0 = low0 + 1;
        const auto low1 = low0 + 2;
        const auto high1 = low0 + 3;
        // Counter-clockwise seen from outside: increasing phi, then up.
        mesh.triangles.push_back({low0, low1, high1});
        mesh.triangles.push_back({low0, high1, high0});
    }
    return mesh;
}

}  // namespace rc
