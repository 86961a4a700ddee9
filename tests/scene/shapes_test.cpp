// pbrt-v4's disk and cylinder as radcache tessellates them (scene/shapes/): against their closed
// forms. The area of every shape within the bound scene/shapes/tessellation.h states (1.01e-4 of
// the exact surface's, and no more than the exact), every vertex on the exact surface, every
// triangle wound towards pbrt's surface normal (the side an area light emits on), and pbrt's
// (u, v) at the vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "scene/shapes/cylinder.h"
#include "scene/shapes/disk.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAreaBound = 1.01e-4;  // scene/shapes/tessellation.h, for a full turn

glm::dvec3 winding(const TriangleMesh& mesh, const glm::uvec3& t) {
    const glm::dvec3 a(mesh.positions[t.x]);
    return glm::cross(glm::dvec3(mesh.positions[t.y]) - a, glm::dvec3(mesh.positions[t.z]) - a);
}

double area(const TriangleMesh& mesh) {
    double sum = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        sum += 0.5 * glm::length(winding(mesh, t));
    }
    return sum;
}

void expect_area(const TriangleMesh& mesh, double exact) {
    const double tessellated = area(mesh);
    EXPECT_LE(tessellated, exact * (1.0 + 1e-6));
    EXPECT_GE(tessellated, exact * (1.0 - kAreaBound)) << tessellated << " of " << exact;
}

TEST(Shapes, DiskAndAnnulusAreFlatFacingPlusZWithPbrtsArea) {
    for (const DiskShape disk :
         {DiskShape{0.5f, 2.0f, 0.0f, 360.0f}, DiskShape{-1.0f, 3.0f, 1.0f, 360.0f},
          DiskShape{0.0f, 1.0f, 0.25f, 90.0f}}) {
        SCOPED_TRACE(disk.inner_radius);
        const TriangleMesh mesh = make_disk(disk);
        const double r = disk.radius;
        const double ri = disk.inner_radius;
        expect_area(mesh, kPi * (r * r - ri * ri) * disk.phi_max_degrees / 360.0);
        for (const glm::uvec3& t : mesh.triangles) {
            const glm::dvec3 n = winding(mesh, t);
            ASSERT_GT(n.z, 0.0);
            ASSERT_NEAR(n.x, 0.0, 1e-6 * n.z);
            ASSERT_NEAR(n.y, 0.0, 1e-6 * n.z);
        }
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec3 p = mesh.positions[v];
            ASSERT_EQ(p.z, disk.height);
            const double radius = std::hypot(p.x, p.y);
            // pbrt's v = (radius - r) / (radius - innerradius): 0 on the rim, 1 on the hole.
            ASSERT_NEAR((r - radius) / (r - ri), mesh.uvs[v].y, 1e-5);
            double phi = std::atan2(p.y, p.x);
            phi = phi < -1e-6 ? phi + 2.0 * kPi : std::max(phi, 0.0);
            const double u = phi / (disk.phi_max_degrees * kPi / 180.0);
            if (radius == 0.0) {
                continue;  // the centre: every u at once
            }
            // The full disk's seam column sits at phi = 0 with u = 1.
            ASSERT_TRUE(std::abs(u - mesh.uvs[v].x) < 1e-4 || (u < 1e-6 && mesh.uvs[v].x == 1.0f))
                << u << " " << mesh.uvs[v].x;
        }
    }
}

TEST(Shapes, CylinderIsOnItsSurfaceWoundOutwardsWithPbrtsArea) {
    for (const CylinderShape cylinder :
         {CylinderShape{1.0f, -1.0f, 1.0f, 360.0f}, CylinderShape{0.5f, 2.0f, 5.0f, 120.0f}}) {
        SCOPED_TRACE(cylinder.phi_max_degrees);
        const TriangleMesh mesh = make_cylinder(cylinder);
        const double r = cylinder.radius;
        const double h = cylinder.z_max - cylinder.z_min;
        expect_area(mesh, 2.0 * kPi * r * h * cylinder.phi_max_degrees / 360.0);
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec3 p = mesh.positions[v];
            ASSERT_NEAR(std::hypot(p.x, p.y), r, 1e-6 * r);
            ASSERT_TRUE(p.z == cylinder.z_min || p.z == cylinder.z_max);
            ASSERT_NEAR(glm::dot(mesh.normals[v], glm::vec3(p.x, p.y, 0.0f)), r, 1e-5 * r);
            ASSERT_EQ(mesh.uvs[v].y, p.z == cylinder.z_min ? 0.0f : 1.0f);
        }
        for (const glm::uvec3& t : mesh.triangles) {
            const glm::dvec3 centroid =
                (glm::dvec3(mesh.positions[t.x]) + glm::dvec3(mesh.positions[t.y]) +
                 glm::dvec3(mesh.positions[t.z])) /
                3.0;
            ASSERT_GT(glm::dot(winding(mesh, t), glm::dvec3(centroid.x, centroid.y, 0.0)), 0.0);
        }
    }
}

}  // namespace
}  // namespace rc
