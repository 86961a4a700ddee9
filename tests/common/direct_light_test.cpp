// Direct light at a point with several light samples and solid-angle sampling of area lights
// (kernels/common/path_radiance.h, light.h, spherical_triangle.h) against independent oracles:
// the closed-form irradiance of a Lambertian polygon (Lambert's formula), solid angles by
// Girard's theorem in double precision, the densities' integral over the sphere, and the
// variance of a mean of independent samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "methods/scene_arguments.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;
using glm::dvec3;

// The light sampler's strategies, as the probe programs are built: the shipped rule, every
// light triangle sampled in solid angle, every one by area.
const char* const kShippedRule = "";
const char* const kAlwaysSolidAngle = "-DRC_SOLID_ANGLE_SAMPLING_MIN=0.0f";
const char* const kAlwaysArea = "-DRC_SOLID_ANGLE_SAMPLING_MIN=INFINITY";
// Irradiance at p (unit normal n) from a Lambertian polygon of unit radiance, the polygon first
// clipped to p's upper half-space: Lambert's formula, E = 1/2 sum_k Theta_k (Gamma_k . n), Theta_k
// the angle the edge k subtends and Gamma_k the unit normal of the plane through p and the edge
// (Arvo, "Applications of Irradiance Tensors", SIGGRAPH 1995, eq. 10).
double polygon_irradiance(const std::vector<dvec3>& polygon, dvec3 p, dvec3 n) {
    std::vector<dvec3> clipped;  // Sutherland-Hodgman against (x - p) . n >= 0
    for (size_t k = 0; k < polygon.size(); ++k) {
        const dvec3 a = polygon[k];
        const dvec3 b = polygon[(k + 1) % polygon.size()];
        const double da = glm::dot(a - p, n);
        const double db = glm::dot(b - p, n);
        if (da >= 0.0) {
            clipped.push_back(a);
        }
        if ((da >= 0.0) != (db >= 0.0)) {
            clipped.push_back(a + (b - a) * (da / (da - db)));
        }
    }
    double sum = 0.0;
    for (size_t k = 0; k < clipped.size(); ++k) {
        const dvec3 u = glm::normalize(clipped[k] - p);
        const dvec3 v = glm::normalize(clipped[(k + 1) % clipped.size()] - p);
        const double theta = std::acos(std::clamp(glm::dot(u, v), -1.0, 1.0));
        sum += theta * glm::dot(glm::normalize(glm::cross(u, v)), n);
    }
    return 0.5 * std::fabs(sum);
}

shared::float4 to_float4(dvec3 v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

// The emitting square [-0.5, 0.5]^2 at z = 0, facing -z, radiance (3, 2, 1); with `blocker`, a
// non-emitting square at z = -4 over x in [-2, 0] (from (0, 0, -8) it hides the light's x < 0
// half).
const glm::vec3 kRadiance(3.0f, 2.0f, 1.0f);
const std::vector<dvec3> kSquare = {
    {-0.5, -0.5, 0.0}, {-0.5, 0.5, 0.0}, {0.5, 0.5, 0.0}, {0.5, -0.5, 0.0}};

Shape generated(const std::string& name, std::vector<glm::vec3> positions,
                std::vector<glm::uvec3> triangles) {
    Shape shape;
    shape.name = name;
    shape.type = "generated";
    shape.mesh.positions = std::move(positions);
    shape.mesh.triangles = std::move(triangles);
    return shape;
}

Scene square_light_scene(bool blocker) {
    Scene scene;
    scene.base_camera.position = {0, 0, -10};
    scene.base_camera.look_at = {0, 0, 0};
    std::vector<glm::vec3> corners;
    for (const dvec3& v : kSquare) {
        corners.push_back(glm::vec3(v));
    }
    Shape light = generated("light", corners, {{0, 1, 2}, {0, 2, 3}});  // winding normal -z
    light.emission = {kRadiance};
    scene.add_shape(light);
    if (blocker) {
        scene.add_shape(generated("blocker", {{-2, -2, -4}, {-2, 2, -4}, {0, 2, -4}, {0, -2, -4}},
                                  {{0, 1, 2}, {0, 2, 3}}));
    }
    scene.set_frame(0.0);
    return scene;
}

// The device side of a probe scene.
struct ProbeScene {
    explicit ProbeScene(Scene s)
        : scene(std::move(s)),
          bvh(build_bvh(scene.mesh, test::shared_context().bvh_layout())),
          device_bvh(test::shared_context(), bvh),
          device_scene(test::shared_context(), scene) {}
    SceneArguments arguments() const { return SceneArguments(device_bvh, device_scene); }
    Scene scene;
    Bvh bvh;
    DeviceBvh device_bvh;
    DeviceScene device_scene;
};

// Per estimate, the light samples' mean and the BRDF sample's part (rgb), from direct_light_probe.
struct DirectEstimates {
    std::vector<shared::float4> light;
    std::vector<shared::float4> brdf;
};

DirectEstimates direct_light(const ProbeScene& s, const char* strategy, dvec3 p, dvec3 n,
                             int light_samples, size_t count, unsigned seed) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("light_probe.cl", "direct_light_probe", strategy);
    Buffer<shared::float4> light(context, count, "light_part");
    Buffer<shared::float4> brdf(context, count, "brdf_part");
    context.launch(kernel, count, to_float4(p), to_float4(glm::normalize(n)), light_samples, seed,
                   s.arguments(), light, brdf);
    return {light.download(), brdf.download()};
}

// Mean and variance of one channel of (light + brdf) or of the light part alone.
struct Moments {
    double mean = 0.0;
    double variance = 0.0;
    double kurtosis = 0.0;  // fourth central moment / variance^2
};

Moments moments(const DirectEstimates& e, int channel, bool light_only) {
    const auto value = [&](size_t i) {
        const float* l = &e.light[i].x;
        const float* b = &e.brdf[i].x;
        return static_cast<double>(l[channel]) + (light_only ? 0.0 : b[channel]);
    };
    const size_t n = e.light.size();
    Moments m;
    for (size_t i = 0; i < n; ++i) {
        m.mean += value(i);
    }
    m.mean /= n;
    double m4 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double d = value(i) - m.mean;
        m.variance += d * d;
        m4 += d * d * d * d;
    }
    m.variance /= n - 1;
    m.kurtosis = m.variance > 0.0 ? m4 / n / (m.variance * m.variance) : 0.0;
    return m;
}

// The direct light's mean at a white Lambertian point is E / pi per channel, E from Lambert's
// formula, within 5 standard errors of the estimates' own variance (and float rounding): with 1
// and several light samples, near and far from the light, across its horizon, half hidden by a
// blocker, with the shipped strategy rule (far: 3e-4 sr per triangle, sampled by area; the
// others in solid angle) and with each strategy forced.
TEST(DirectLight, MeanIsTheClosedFormIrradianceOfThePolygon) {
    struct Case {
        const char* name;
        dvec3 p;
        dvec3 n;
        bool blocker;
    };
    const Case cases[] = {
        {"far", {0.3, -0.2, -40.0}, {0.2, 0.1, 1.0}, false},
        {"near", {0.1, 0.05, -0.15}, {0.3, -0.2, 1.0}, false},
        {"horizon", {0.45, 0.0, -0.1}, {1.0, 0.0, 2.0}, false},
        {"blocked", {0.0, 0.0, -8.0}, {0.0, 0.0, 1.0}, true},
    };
    const ProbeScene open(square_light_scene(false));
    const ProbeScene blocked(square_light_scene(true));
    const size_t count = 1 << 16;
    for (const Case& c : cases) {
        const dvec3 n = glm::normalize(c.n);
        std::vector<dvec3> visible = kSquare;
        if (c.blocker) {
            visible = {{0.0, -0.5, 0.0}, {0.0, 0.5, 0.0}, {0.5, 0.5, 0.0}, {0.5, -0.5, 0.0}};
        }
        const double irradiance = polygon_irradiance(visible, c.p, n);
        for (const char* strategy : {kShippedRule, kAlwaysSolidAngle, kAlwaysArea}) {
            for (int light_samples : {1, 3}) {
                const DirectEstimates e = direct_light(c.blocker ? blocked : open, strategy, c.p, n,
                                                       light_samples, count, 17);
                for (int channel = 0; channel < 3; ++channel) {
                    const double expected = kRadiance[channel] * irradiance / kPi;
                    const Moments m = moments(e, channel, false);
                    const double bound =
                        5.0 * std::sqrt(m.variance / count) + 2e-4 * expected + 1e-7;
                    EXPECT_NEAR(m.mean, expected, bound)
                        << c.name << " '" << strategy << "' light samples " << light_samples
                        << " channel " << channel;
                }
            }
        }
    }
}

// The light samples' mean with N samples has 1 / N of the variance with one (independent
// samples): far from the light, half of it hidden, where the MIS weights are 1 to within 3e-5 so
// that one sample's distribution does not depend on N. Bound: 5 standard errors of the ratio of
// two sample variances, from their kurtosis.
TEST(DirectLight, VarianceOfTheLightSamplesFallsAsOneOverTheirCount) {
    const ProbeScene s(square_light_scene(true));
    const size_t count = 1 << 16;
    const dvec3 p(0.0, 0.0, -8.0);
    const dvec3 n(0.0, 0.0, 1.0);
    const Moments one = moments(direct_light(s, kShippedRule, p, n, 1, count, 5), 0, true);
    ASSERT_GT(one.variance, 0.0);
    for (int light_samples : {2, 4, 8}) {
        const Moments many =
            moments(direct_light(s, kShippedRule, p, n, light_samples, count, 6), 0, true);
        const double ratio = many.variance * light_samples / one.variance;
        const double error =
            ratio * std::sqrt((one.kurtosis - 1.0) / count + (many.kurtosis - 1.0) / count);
        EXPECT_NEAR(ratio, 1.0, 5.0 * error) << light_samples << " light samples";
    }
}

// Each estimate traces its N shadow rays and one BRDF ray at most: the count of light samples
// is what the kernel takes.
TEST(DirectLight, EstimateTracesOneShadowRayPerLightSampleAndOneBrdfRay) {
    const ProbeScene s(square_light_scene(false));
    for (int light_samples : {1, 5}) {
        const DirectEstimates e =
            direct_light(s, kShippedRule, {0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}, light_samples, 256, 3);
        for (const shared::float4& l : e.light) {
            EXPECT_EQ(l.w, static_cast<float>(light_samples + 1));
        }
    }
}

// Same seed, same estimates, bit for bit; another seed, other estimates.
TEST(DirectLight, SameSeedGivesBitwiseIdenticalEstimates) {
    const ProbeScene s(square_light_scene(true));
    const DirectEstimates a =
        direct_light(s, kShippedRule, {0.1, 0.0, -0.3}, {0.0, 0.0, 1.0}, 4, 4096, 8);
    const DirectEstimates b =
        direct_light(s, kShippedRule, {0.1, 0.0, -0.3}, {0.0, 0.0, 1.0}, 4, 4096, 8);
    ASSERT_EQ(a.light.size(), b.light.size());
    EXPECT_EQ(std::memcmp(a.light.data(), b.light.data(), a.light.size() * sizeof(shared::float4)),
              0);
    EXPECT_EQ(std::memcmp(a.brdf.data(), b.brdf.data(), a.brdf.size() * sizeof(shared::float4)), 0);
    const DirectEstimates c =
        direct_light(s, kShippedRule, {0.1, 0.0, -0.3}, {0.0, 0.0, 1.0}, 4, 4096, 9);
    EXPECT_NE(std::memcmp(a.light.data(), c.light.data(), a.light.size() * sizeof(shared::float4)),
              0);
}

}  // namespace
}  // namespace rc
