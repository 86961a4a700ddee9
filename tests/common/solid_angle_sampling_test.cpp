// Solid-angle sampling of area-light triangles (kernels/common/spherical_triangle.h, Arvo 1995)
// and the light sampler's choice between it and sampling by area (kernels/common/light.h):
// directions land in the triangle and are uniform in solid angle (chi-square over sub-triangles
// whose solid angles Girard's theorem gives in double precision); the density light sampling
// reports is the one MIS evaluates for the same direction, is the formula of the strategy the
// geometry selects, and integrates to one over the sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <string>
#include <vector>

#include "chi_square.h"
#include "methods/scene_arguments.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;
using glm::dvec3;

// kernels/common/light.h's RC_SOLID_ANGLE_SAMPLING_MIN.
constexpr double kShippedMinSolidAngle = 1e-3;

// The light sampler's strategies as the probe programs are built: the shipped rule, every light
// triangle sampled in solid angle, every one by area; and the threshold each applies.
struct Strategy {
    const char* options;
    double min_solid_angle;
};
const Strategy kStrategies[] = {
    {"", kShippedMinSolidAngle},
    {"-DRC_SOLID_ANGLE_SAMPLING_MIN=0.0f", 0.0},
    {"-DRC_SOLID_ANGLE_SAMPLING_MIN=INFINITY", INFINITY},
};

// Girard's theorem: the solid angle of the spherical triangle a b c (directions of any length)
// is its angle excess; each angle is the one between the planes through the vertex and its two
// neighbours.
double girard_solid_angle(dvec3 a, dvec3 b, dvec3 c) {
    const auto angle = [](dvec3 at, dvec3 x, dvec3 y) {
        const dvec3 nx = glm::normalize(glm::cross(at, x));
        const dvec3 ny = glm::normalize(glm::cross(at, y));
        return std::acos(std::clamp(glm::dot(nx, ny), -1.0, 1.0));
    };
    return angle(a, b, c) + angle(b, c, a) + angle(c, a, b) - kPi;
}

shared::float4 to_float4(dvec3 v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

dvec3 to_dvec3(const shared::float4& v) { return {v.x, v.y, v.z}; }

// Barycentrics (of v1, v2) where the ray from the origin along d meets the plane of v0 v1 v2.
glm::dvec2 plane_barycentrics(dvec3 d, dvec3 v0, dvec3 v1, dvec3 v2) {
    const dvec3 e1 = v1 - v0;
    const dvec3 e2 = v2 - v0;
    const dvec3 normal = glm::cross(e1, e2);
    const dvec3 q = d * (glm::dot(v0, normal) / glm::dot(d, normal)) - v0;
    const double d11 = glm::dot(e1, e1);
    const double d12 = glm::dot(e1, e2);
    const double d22 = glm::dot(e2, e2);
    const double q1 = glm::dot(q, e1);
    const double q2 = glm::dot(q, e2);
    const double det = d11 * d22 - d12 * d12;
    return {(d22 * q1 - d12 * q2) / det, (d11 * q2 - d12 * q1) / det};
}

// The spherical-triangle sampler from the origin: every direction meets the planar triangle,
// and the counts in the k^2 sub-triangles of its barycentric subdivision follow their solid
// angles; the solid angle it reports is Girard's.
TEST(SolidAngleSampling, SphericalTriangleDirectionsAreUniformInsideTheTriangle) {
    struct Case {
        const char* name;
        dvec3 v0, v1, v2;
    };
    const Case cases[] = {
        {"moderate", {-0.3, -0.2, 1.0}, {0.8, -0.1, 1.0}, {0.1, 0.9, 1.0}},
        {"beyond pi", {-2.0, -1.0, 0.2}, {2.0, -1.5, 0.2}, {0.5, 2.0, 0.2}},
        {"thin", {-1.0, 0.0, 1.0}, {1.0, 0.05, 1.0}, {0.9, 0.1, 1.2}},
        {"small", {-0.3, -0.2, 30.0}, {0.8, -0.1, 30.0}, {0.1, 0.9, 30.0}},
        {"tiny", {-0.3, -0.2, 300.0}, {0.8, -0.1, 300.0}, {0.1, 0.9, 300.0}},
    };
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("light_probe.cl", "spherical_triangle_probe");
    const size_t count = 1 << 18;
    const int k = 8;  // subdivisions per edge: k^2 bins
    for (const Case& c : cases) {
        Buffer<shared::float4> directions(context, count, "directions");
        context.launch(kernel, count, to_float4(glm::normalize(c.v0)),
                       to_float4(glm::normalize(c.v1)), to_float4(glm::normalize(c.v2)), 23u,
                       directions);
        const std::vector<shared::float4> d = directions.download();
        const double total = girard_solid_angle(c.v0, c.v1, c.v2);
        EXPECT_NEAR(d[0].w, total, 1e-4 * total) << c.name;
        // Bin (i, j, upper): the sub-triangle of barycentrics (b1, b2) in cell (i, j).
        std::vector<double> observed(k * k, 0.0);
        std::vector<double> expected(k * k, 0.0);
        const auto corner = [&](int i, int j) {
            const double b1 = static_cast<double>(i) / k;
            const double b2 = static_cast<double>(j) / k;
            return c.v0 + b1 * (c.v1 - c.v0) + b2 * (c.v2 - c.v0);
        };
        int bin = 0;
        std::vector<int> bin_of(2 * k * k, -1);  // (i * k + j) * 2 + upper
        for (int i = 0; i < k; ++i) {
            for (int j = 0; i + j < k; ++j) {
                expected[bin] =
                    count * girard_solid_angle(corner(i, j), corner(i + 1, j), corner(i, j + 1)) /
                    total;
                bin_of[(i * k + j) * 2] = bin++;
                if (i + j + 1 < k) {
                    expected[bin] = count *
                                    girard_solid_angle(corner(i + 1, j), corner(i + 1, j + 1),
                                                       corner(i, j + 1)) /
                                    total;
                    bin_of[(i * k + j) * 2 + 1] = bin++;
                }
            }
        }
        ASSERT_EQ(bin, k * k);
        size_t outside = 0;
        for (const shared::float4& direction : d) {
            const glm::dvec2 b = plane_barycentrics(to_dvec3(direction), c.v0, c.v1, c.v2);
            const double slack = 1e-4;
            if (b.x < -slack || b.y < -slack || b.x + b.y > 1.0 + slack) {
                ++outside;
                continue;
            }
            const double x = std::clamp(b.x, 0.0, 1.0 - 1e-12) * k;
            const double y = std::clamp(b.y, 0.0, 1.0 - 1e-12) * k;
            int i = static_cast<int>(x);
            int j = static_cast<int>(y);
            if (i + j >= k) {  // rounding past the hypotenuse: the last lower sub-triangle
                j = k - 1 - i;
            }
            const bool upper = (x - i) + (y - j) > 1.0 && i + j + 1 < k;
            observed[bin_of[(i * k + j) * 2 + (upper ? 1 : 0)]] += 1.0;
        }
        EXPECT_EQ(outside, 0u) << c.name;
        const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
        EXPECT_GT(chi.p_value, 1e-4) << c.name << ": " << chi.summary();
    }
}

// An 8 x 1 strip of 16 emitting triangles at z = 0 facing -z, seen from p near one end: the near
// triangles subtend more than the shipped threshold, the far ones less.
const dvec3 kStripPoint(0.3, 0.1, -0.3);
constexpr int kStripSquares = 8;

// Triangle t of the strip: square t / 2, its upper-left (v >= u) or lower-right half.
std::array<dvec3, 3> strip_triangle(int t) {
    const double x = t / 2;
    if (t % 2 == 0) {
        return {dvec3(x, -0.5, 0.0), dvec3(x, 0.5, 0.0), dvec3(x + 1.0, 0.5, 0.0)};
    }
    return {dvec3(x, -0.5, 0.0), dvec3(x + 1.0, 0.5, 0.0), dvec3(x + 1.0, -0.5, 0.0)};
}

Scene strip_scene() {
    Scene scene;
    scene.base_camera.position = {4, 0, -10};
    scene.base_camera.look_at = {4, 0, 0};
    Shape strip;
    strip.name = "strip";
    strip.type = "generated";
    for (int t = 0; t < 2 * kStripSquares; ++t) {
        const unsigned first = static_cast<unsigned>(strip.mesh.positions.size());
        for (const dvec3& v : strip_triangle(t)) {
            strip.mesh.positions.push_back(glm::vec3(v));
        }
        strip.mesh.triangles.push_back({first, first + 1, first + 2});
    }
    strip.emission = {glm::vec3(1.0f)};
    scene.add_shape(strip);
    scene.set_frame(0.0);
    return scene;
}

struct StripProbe {
    StripProbe()
        : scene(strip_scene()),
          bvh(build_bvh(scene.mesh, test::shared_context().bvh_layout())),
          device_bvh(test::shared_context(), bvh),
          device_scene(test::shared_context(), scene) {}

    // Light sampling's densities for `directions` from kStripPoint.
    std::vector<float> pdfs(const char* strategy, const std::vector<shared::float4>& directions) {
        Context& context = test::shared_context();
        Kernel kernel = context.kernel("light_probe.cl", "light_pdf_probe", strategy);
        Buffer<shared::float4> d(context, directions.size(), "directions");
        d.upload(directions);
        Buffer<float> out(context, directions.size(), "pdfs");
        context.launch(kernel, directions.size(), to_float4(kStripPoint),
                       SceneArguments(device_bvh, device_scene), d, out);
        return out.download();
    }

    Scene scene;
    Bvh bvh;
    DeviceBvh device_bvh;
    DeviceScene device_scene;
};

// The density of light sampling over the sphere integrates to one, whichever strategies the
// triangles take: uniform directions over the half-space towards the strip (the other half
// never reaches its emitting side), 2 pi times the mean density, within 5 standard errors.
TEST(SolidAngleSampling, LightDensityIntegratesToOne) {
    int near = 0;
    for (int t = 0; t < 2 * kStripSquares; ++t) {
        const std::array<dvec3, 3> v = strip_triangle(t);
        near += girard_solid_angle(v[0] - kStripPoint, v[1] - kStripPoint, v[2] - kStripPoint) >=
                        kShippedMinSolidAngle
                    ? 1
                    : 0;
    }
    ASSERT_GT(near, 0);
    ASSERT_LT(near, 2 * kStripSquares);  // both strategies under the shipped rule
    const size_t count = 1 << 20;
    std::mt19937_64 random(99);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<shared::float4> directions(count);
    for (shared::float4& d : directions) {
        const double z = uniform(random);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = 2.0 * kPi * uniform(random);
        d = to_float4({r * std::cos(phi), r * std::sin(phi), z});
    }
    StripProbe probe;
    for (const Strategy& strategy : kStrategies) {
        const std::vector<float> pdf = probe.pdfs(strategy.options, directions);
        double sum = 0.0;
        double sum2 = 0.0;
        for (float v : pdf) {
            sum += v;
            sum2 += static_cast<double>(v) * v;
        }
        const double mean = sum / count;
        const double variance = (sum2 / count - mean * mean) * count / (count - 1);
        const double integral = 2.0 * kPi * mean;
        EXPECT_NEAR(integral, 1.0, 5.0 * 2.0 * kPi * std::sqrt(variance / count))
            << "'" << strategy.options << "'";
    }
}

// The density light sampling reports for its sample is the density MIS evaluates for the same
// direction (a ray from p to the light), and it is the formula of the strategy the geometry
// selects: selection x (A_t / A) / Omega_t in solid angle, selection x d^2 / (A cos) by area,
// Omega_t by Girard's theorem in double precision.
TEST(SolidAngleSampling, SampledDensityIsTheEvaluatedOneOfTheSelectedStrategy) {
    StripProbe probe;
    Context& context = test::shared_context();
    const size_t count = 1 << 16;
    const double area = kStripSquares;
    for (const Strategy& strategy : kStrategies) {
        const double threshold = strategy.min_solid_angle;
        Kernel kernel = context.kernel("light_probe.cl", "light_sample_probe", strategy.options);
        Buffer<shared::float4> choice(context, count, "choice");
        Buffer<shared::float4> geometry(context, 2 * count, "geometry");
        Buffer<shared::float4> radiance(context, count, "radiance");
        context.launch(kernel, count, to_float4(kStripPoint), 41u,
                       SceneArguments(probe.device_bvh, probe.device_scene), choice, geometry,
                       radiance);
        const std::vector<shared::float4> c = choice.download();
        const std::vector<shared::float4> g = geometry.download();
        std::vector<shared::float4> directions(count);
        for (size_t i = 0; i < count; ++i) {
            directions[i] = g[2 * i];
        }
        const std::vector<float> evaluated = probe.pdfs(strategy.options, directions);
        size_t disagreements = 0;
        size_t checked = 0;
        for (size_t i = 0; i < count; ++i) {
            ASSERT_GT(c[i].y, 0.0f);
            if (std::fabs(evaluated[i] - c[i].y) > 1e-3f * c[i].y) {
                ++disagreements;  // a ray along a shared edge may meet the neighbour
            }
            // The sampled triangle, from the point (off the diagonal and the squares' edges).
            const dvec3 q = to_dvec3(g[2 * i + 1]);
            const double u = q.x - std::floor(q.x);
            const double v = q.y + 0.5;
            if (std::fabs(u - v) < 1e-3 || u < 1e-3 || u > 1.0 - 1e-3) {
                continue;
            }
            const int t = 2 * static_cast<int>(std::floor(q.x)) + (v >= u ? 0 : 1);
            const std::array<dvec3, 3> tri = strip_triangle(t);
            const double omega = girard_solid_angle(tri[0] - kStripPoint, tri[1] - kStripPoint,
                                                    tri[2] - kStripPoint);
            if (std::isfinite(threshold) && std::fabs(omega - threshold) < 1e-3 * threshold) {
                continue;  // too close to the threshold to tell in float
            }
            const dvec3 to = q - kStripPoint;
            const double d2 = glm::dot(to, to);
            const double expected =
                omega >= threshold ? (0.5 / area) / omega : d2 / (area * (to.z / std::sqrt(d2)));
            EXPECT_NEAR(c[i].y, expected, 1e-3 * expected)
                << "'" << strategy.options << "' triangle " << t;
            ++checked;
            if (::testing::Test::HasFailure()) {
                return;
            }
        }
        EXPECT_LE(disagreements, count / 10000) << "'" << strategy.options << "'";
        EXPECT_GT(checked, count / 2);
    }
}

}  // namespace
}  // namespace rc
