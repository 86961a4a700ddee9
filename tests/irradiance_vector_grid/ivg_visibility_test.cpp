// The grid lookup's corner visibility (kernels/common/ivg_visibility.h, the cells'
// planes of host/methods/grid/ivg_cell_planes.h) against the shadow rays it
// skips: at the hits of random rays in three scenes, the corners it finds visible must be those
// eight shadow rays find, and some lookups must trace fewer than eight. The triangle-box test
// under the cells' planes against clipping the triangle to the box.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <random>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/grid/triangle_box_overlap.h"
#include "methods/scene_arguments.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A scene with its device side and a grid (auto cells, all values zero: only the visibility is
// probed) over it.
struct GridScene {
    explicit GridScene(Scene s, IvgOptions options = {})
        : scene(std::move(s)),
          bvh(build_bvh(scene.mesh, test::shared_context().bvh_layout())),
          device_bvh(test::shared_context(), bvh),
          device_scene(test::shared_context(), scene),
          grid({test::shared_context(), scene, device_bvh, device_scene}) {
        grid.set_params(grid.layout(options));
        grid.set_values(std::vector<float>(
            static_cast<size_t>(grid.params().vertex_count) * RC_IVG_VALUES_PER_VERTEX, 0.0f));
    }
    Scene scene;
    Bvh bvh;
    DeviceBvh device_bvh;
    DeviceScene device_scene;
    IrradianceVectorGrid grid;
};

struct Lookup {
    unsigned classified = 0;  // corners rc_ivg_visible_corners finds visible
    unsigned all_rays = 0;    // corners eight shadow rays find visible
    unsigned traced = 0;      // rays rc_ivg_visible_corners traced
    bool hit = false;
};

std::vector<Lookup> probe(GridScene& g, const std::vector<shared::Ray>& rays) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("ivg_visibility_probe.cl", "ivg_visibility_probe");
    const Buffer<shared::Ray> ray_buffer(context, rays, "probe_rays");
    Buffer<shared::uint4> out(context, rays.size(), "probe_out");
    context.launch(kernel, rays.size(), g.grid, SceneArguments(g.device_bvh, g.device_scene),
                   ray_buffer, out);
    std::vector<Lookup> lookups;
    for (const shared::uint4& o : out.download()) {
        lookups.push_back({o.x, o.y, o.z, o.w != 0});
    }
    return lookups;
}

shared::Ray make_ray(glm::vec3 origin, glm::vec3 direction) {
    shared::Ray r{};
    r.origin = {origin.x, origin.y, origin.z, 0.0f};
    r.direction = {direction.x, direction.y, direction.z, INFINITY};
    return r;
}

// Rays from uniform points of the grid's box in uniform directions.
std::vector<shared::Ray> random_rays(const shared::IvgParams& p, size_t count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<shared::Ray> rays;
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 origin(p.origin.x + u(rng) * p.cells.x * p.cell.x,
                               p.origin.y + u(rng) * p.cells.y * p.cell.y,
                               p.origin.z + u(rng) * p.cells.z * p.cell.z);
        const float z = 1.0f - 2.0f * u(rng);
        const float phi = 2.0f * static_cast<float>(kPi) * u(rng);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        rays.push_back(make_ray(origin, {r * std::cos(phi), r * std::sin(phi), z}));
    }
    return rays;
}

void expect_same_corners_with_fewer_rays(const std::string& name) {
    GridScene g(load_scene(test::source_dir() / "scenes" / name / "scene.json"));
    const std::vector<Lookup> lookups = probe(g, random_rays(g.grid.params(), 20000, 15));
    size_t hits = 0;
    size_t cheaper = 0;
    size_t mismatches = 0;
    size_t rays = 0;
    for (const Lookup& l : lookups) {
        if (!l.hit) {
            continue;
        }
        ++hits;
        cheaper += l.traced < 8 ? 1 : 0;
        mismatches += l.classified != l.all_rays ? 1 : 0;
        rays += l.traced;
    }
    EXPECT_EQ(mismatches, 0u) << name;
    EXPECT_GT(hits, 10000u) << name;
    EXPECT_GT(cheaper, 0u) << name;
    std::printf("%s: %zu lookups, %.1f%% traced fewer than 8 rays, %.3f rays per lookup\n",
                name.c_str(), hits, 100.0 * cheaper / hits, static_cast<double>(rays) / hits);
}

TEST(IvgVisibility, CornellBoxSeesTheCornersItsShadowRaysSee) {
    expect_same_corners_with_fewer_rays("cornell-box");
}

TEST(IvgVisibility, TwoRoomsSeesTheCornersItsShadowRaysSee) {
    expect_same_corners_with_fewer_rays("two-rooms");
}

TEST(IvgVisibility, ReliefSeesTheCornersItsShadowRaysSee) {
    expect_same_corners_with_fewer_rays("relief");
}

Shape quad(const std::string& name, std::vector<glm::vec3> corners) {
    Shape shape;
    shape.name = name;
    shape.type = "generated";
    shape.mesh.positions = std::move(corners);
    shape.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return shape;
}

// A floor y = 0 over [-1, 1]^2 and a ceiling at y = 1 (grid 4 x 4 x 4: cells 0.5 x 0.25 x 0.5), and
// a thin wall x = 0.2, y in [0, 0.1], z in [0.1, 0.4], inside the floor's cell [0, 0.5] x [0,
// 0.25] x [0, 0.5]. In that cell the wall stands above the floor's plane and the floor extends on
// both sides of the wall's: no plane leaves the side of a point on the floor free, so it traces
// all eight rays, and the wall hides corners from it. A point on the floor in a cell of the floor
// alone skips the rays to the cell's upper corners (the lower ones lie on the floor's plane).
TEST(IvgVisibility, PointBesideAThinWallTracesEveryCorner) {
    Scene scene;
    scene.base_camera.position = {0, 0.5f, -3};
    scene.base_camera.look_at = {0, 0.5f, 0};
    scene.add_shape(quad("floor", {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}));
    scene.add_shape(quad("ceiling", {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}}));
    scene.add_shape(
        quad("wall", {{0.2f, 0, 0.1f}, {0.2f, 0.1f, 0.1f}, {0.2f, 0.1f, 0.4f}, {0.2f, 0, 0.4f}}));
    scene.set_frame(0.0);
    IvgOptions options;
    options.cells = {4, 4, 4};
    GridScene g(std::move(scene), options);
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    const std::vector<Lookup> lookups =
        probe(g, {make_ray({0.3f, 0.5f, 0.25f}, down), make_ray({0.1f, 0.5f, 0.25f}, down),
                  make_ray({-0.7f, 0.5f, -0.7f}, down)});
    for (const Lookup& l : lookups) {
        ASSERT_TRUE(l.hit);
        EXPECT_EQ(l.classified, l.all_rays);
    }
    EXPECT_EQ(lookups[0].traced, 8u);
    EXPECT_EQ(lookups[1].traced, 8u);
    EXPECT_NE(lookups[0].all_rays, 0xffu);  // the wall hides the cell's corners at x = 0
    EXPECT_NE(lookups[1].all_rays, 0xffu);  // and at x = 0.5
    EXPECT_EQ(lookups[2].traced, 4u);
}

// Oracle of the triangle-box test: the triangle clipped to the box's six half-spaces
// (Sutherland-Hodgman) keeps a point exactly when they overlap.
bool clipped_triangle_is_empty(const std::vector<glm::dvec3>& triangle, glm::dvec3 lower,
                               glm::dvec3 upper) {
    std::vector<glm::dvec3> polygon = triangle;
    for (int axis = 0; axis < 3 && !polygon.empty(); ++axis) {
        for (int side = 0; side < 2 && !polygon.empty(); ++side) {
            // Keep s * (x[axis] - bound) <= 0.
            const double s = side == 0 ? -1.0 : 1.0;
            const double bound = side == 0 ? lower[axis] : upper[axis];
            std::vector<glm::dvec3> kept;
            for (size_t k = 0; k < polygon.size(); ++k) {
                const glm::dvec3 a = polygon[k];
                const glm::dvec3 b = polygon[(k + 1) % polygon.size()];
                const double da = s * (a[axis] - bound);
                const double db = s * (b[axis] - bound);
                if (da <= 0.0) {
                    kept.push_back(a);
                }
                if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
                    kept.push_back(a + (b - a) * (da / (da - db)));
                }
            }
            polygon = kept;
        }
    }
    return polygon.empty();
}

TEST(TriangleBoxOverlap, AgreesWithClippingTheTriangleToTheBox) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dvec3 lower(-0.3, -0.2, -0.1);
    const glm::dvec3 upper(0.1, 0.3, 0.2);
    int overlaps = 0;
    int separate = 0;
    int separate_by_edges_or_plane = 0;  // the bounding boxes overlap, the shapes do not
    for (int trial = 0; trial < 20000; ++trial) {
        const glm::dvec3 centre = 0.6 * glm::dvec3(u(rng), u(rng), u(rng));
        const double size = 0.6 * (u(rng) + 1.0);
        std::vector<glm::dvec3> triangle;
        for (int v = 0; v < 3; ++v) {
            triangle.push_back(centre + size * glm::dvec3(u(rng), u(rng), u(rng)));
        }
        const bool expected = !clipped_triangle_is_empty(triangle, lower, upper);
        ASSERT_EQ(triangle_overlaps_box(triangle[0], triangle[1], triangle[2], lower, upper),
                  expected)
            << "trial " << trial;
        (expected ? overlaps : separate) += 1;
        const glm::dvec3 t_lower = glm::min(triangle[0], glm::min(triangle[1], triangle[2]));
        const glm::dvec3 t_upper = glm::max(triangle[0], glm::max(triangle[1], triangle[2]));
        const bool boxes_overlap = glm::all(glm::lessThanEqual(t_lower, upper)) &&
                                   glm::all(glm::lessThanEqual(lower, t_upper));
        separate_by_edges_or_plane += !expected && boxes_overlap ? 1 : 0;
    }
    EXPECT_GT(overlaps, 2000);
    EXPECT_GT(separate, 2000);
    EXPECT_GT(separate_by_edges_or_plane, 500);
    std::printf("%d overlap, %d separate (%d with overlapping bounding boxes)\n", overlaps,
                separate, separate_by_edges_or_plane);
}

}  // namespace
}  // namespace rc
