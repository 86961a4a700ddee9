// pbrt's loopsubdiv (scene/shapes/loop_subdivision.h) against Loop's own results: an octahedron
// refined three times is closed, inside its control polyhedron, 8 x 4^3 triangles, and its
// control vertex (0, 0, 1) lands where Loop's limit mask puts it (Loop 1987; the mask
// v = (1 - n g) v0 + g sum of the n neighbours, g = 1 / (n + 3 / (8 b)), b = (5/8 - (3/8 +
// cos(2 pi / n) / 4)^2) / n, as pbrt-v3 §3.8.4 states it), with the normal of the symmetric
// surface there; a planar mesh stays in its plane, normals on its winding's side; the pbrt
// import reads the shape, and a subdivision past the triangle bound is refused.
#include "scene/shapes/loop_subdivision.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "scene/scene_loader.h"
#include "scratch_files.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

TriangleMesh octahedron() {
    TriangleMesh m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    // Outward (counter-clockwise seen from outside).
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

TEST(LoopSubdivision, OctahedronMeetsLoopsLimitMask) {
    const TriangleMesh mesh = make_loop_subdivision(octahedron(), 3);
    ASSERT_EQ(mesh.triangles.size(), 8u * 64u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    // Closed: every edge in exactly two triangles, once in each direction.
    std::map<std::pair<unsigned, unsigned>, int> edges;
    for (const glm::uvec3& t : mesh.triangles) {
        for (int i = 0; i < 3; ++i) {
            ++edges[{t[i], t[(i + 1) % 3]}];
        }
    }
    for (const auto& [edge, count] : edges) {
        EXPECT_EQ(count, 1);
        EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
    }
    for (const glm::vec3& p : mesh.positions) {
        EXPECT_LE(std::abs(p.x) + std::abs(p.y) + std::abs(p.z), 1.0f + 1e-5f);
    }
    const double pi = 3.14159265358979323846;
    const int n = 4;
    const double b = (5.0 / 8.0 - std::pow(3.0 / 8.0 + std::cos(2 * pi / n) / 4.0, 2)) / n;
    const double g = 1.0 / (n + 3.0 / (8.0 * b));
    const double pole = 1.0 - n * g;  // the neighbours sum to 0
    int found = 0;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p = mesh.positions[i];
        if (std::abs(p.x) < 1e-6f && std::abs(p.y) < 1e-6f && p.z > 0.0f) {
            ++found;
            EXPECT_NEAR(p.z, pole, 1e-5);
            EXPECT_NEAR(mesh.normals[i].z, 1.0f, 1e-5f);
        }
    }
    EXPECT_EQ(found, 1);
}

TEST(LoopSubdivision, PlanarMeshStaysInItsPlane) {
    TriangleMesh square;
    square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    const TriangleMesh mesh = make_loop_subdivision(square, 2);
    ASSERT_EQ(mesh.triangles.size(), 32u);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        EXPECT_EQ(mesh.positions[i].z, 0.0f);
        EXPECT_GE(mesh.positions[i].x, -1e-6f);
        EXPECT_LE(mesh.positions[i].x, 1.0f + 1e-6f);
        EXPECT_NEAR(mesh.normals[i].z, 1.0f, 1e-6f);  // counter-clockwise seen from +z
    }
    EXPECT_THROW(make_loop_subdivision(square, 12), Error);  // 2 x 4^12 > 2^24 triangles
}

TEST(LoopSubdivision, PbrtImportReadsTheShape) {
    const auto dir = test::scratch_dir("pbrt_loopsubdiv");
    const std::string header =
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "LightSource \"point\" \"point3 from\" [0 0 -4]\n";
    const std::string shape =
        "Shape \"loopsubdiv\" \"point3 P\" [1 0 0 -1 0 0 0 1 0 0 -1 0 0 0 1 0 0 -1]\n"
        "    \"integer indices\" [0 2 4 2 1 4 1 3 4 3 0 4 2 0 5 1 2 5 3 1 5 0 3 5]";
    const auto file =
        test::write_file(dir / "loop.pbrt", header + shape + " \"integer levels\" 2\n");
    const Scene scene = load_scene(file);
    EXPECT_EQ(scene.mesh.triangle_count(), 8u * 16u);
    const auto refused =
        test::write_file(dir / "deep.pbrt", header + shape + " \"integer levels\" 11\n");
    const test::CommandResult result =
        test::run_radcache({"render", refused.string(), "-o", (dir / "deep.png").string(), "-q"});
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("exceed"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "deep.png"));
}

}  // namespace
}  // namespace rc
