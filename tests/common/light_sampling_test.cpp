// Light sampling for next-event estimation (kernels/common/light.h): lights chosen in
// proportion to power, points uniform by area on area lights (the strategy for triangles under a
// small solid angle; tests/common/solid_angle_sampling_test.cpp tests the other), pdfs that are the
// solid-angle densities, and the radiance of point, spot and distant lights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "chi_square.h"
#include "image/image_io.h"
#include "methods/scene_arguments.h"
#include "scene/device_scene.h"
#include "scene/environment_map.h"
#include "scene/generated_meshes.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 2 x 1 quad light facing -z at z = 2 (radiance 4, 2, 1), a small triangle light, a point
// light and a spot light.
Scene light_scene() {
    Scene scene;
    scene.base_camera.position = {0, 0, -5};
    scene.base_camera.look_at = {0, 0, 0};
    Shape quad;
    quad.name = "quad";
    quad.type = "rectangle";
    quad.mesh = make_rectangle();
    // Scale to 2 x 1, turn to face -z, move to z = 2.
    quad.transform = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 2.0f)) *
                     glm::rotate(glm::mat4(1.0f), glm::radians(180.0f), glm::vec3(0, 1, 0)) *
                     glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.5f, 1.0f));
    quad.emission = {glm::vec3(4.0f, 2.0f, 1.0f)};
    scene.add_shape(quad);
    Shape small;
    small.name = "triangle";
    small.type = "generated";
    small.mesh.positions = {{-2, 1, 1}, {-2, 1.2f, 1}, {-1.8f, 1, 1}};
    small.mesh.triangles = {{0, 1, 2}};  // faces -z
    small.emission = {glm::vec3(10.0f)};
    scene.add_shape(small);
    Emitter point;
    point.name = "point";
    point.kind = EmitterKind::kPoint;
    point.position = {0, 3, 0};
    point.intensity = glm::vec3(2.0f);
    scene.emitters.push_back(point);
    Emitter spot;
    spot.name = "spot";
    spot.kind = EmitterKind::kSpot;
    spot.position = {0, 0, -3};
    spot.look_at = {0, 0, 0};
    spot.intensity = glm::vec3(5.0f);
    spot.cutoff_angle = 30.0f;
    spot.beam_width = 20.0f;
    scene.emitters.push_back(spot);
    scene.set_frame(0.0);
    return scene;
}

struct ProbeResult {
    std::vector<shared::float4> choice;    // x: light, y: pdf, z: delta, w: infinite
    std::vector<shared::float4> geometry;  // direction, target per sample
    std::vector<shared::float4> radiance;
};

// `options`: the probe program's build options (-D).
ProbeResult probe(const Scene& scene, glm::vec3 p, size_t count, unsigned seed,
                  const std::string& options = "") {
    Context& context = test::shared_context();
    const Bvh bvh = build_bvh(scene.mesh, context.bvh_layout());
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    Kernel kernel = context.kernel("light_probe.cl", "light_sample_probe", options);
    Buffer<shared::float4> choice(context, count, "choice");
    Buffer<shared::float4> geometry(context, 2 * count, "geometry");
    Buffer<shared::float4> radiance(context, count, "radiance");
    const shared::float4 point = {p.x, p.y, p.z, 0.0f};
    context.launch(kernel, count, point, seed, SceneArguments(device_bvh, device_scene), choice,
                   geometry, radiance);
    return {choice.download(), geometry.download(), radiance.download()};
}

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

TEST(LightSampling, LightsAreChosenInProportionToPower) {
    const Scene scene = light_scene();
    ASSERT_EQ(scene.lights.lights.size(), 4u);
    // Powers: area pi A lum(L); point 4 pi lum(I); spot 2 pi (1 - cos((cutoff + beam) / 2)) lum(I).
    const double power[4] = {kPi * 2.0 * luminance({4, 2, 1}), kPi * 0.02 * 10.0, 4.0 * kPi * 2.0,
                             2.0 * kPi * (1.0 - std::cos(25.0 * kPi / 180.0)) * 5.0};
    const double total = power[0] + power[1] + power[2] + power[3];
    const size_t n = 1 << 20;
    const ProbeResult r = probe(scene, {0.1f, 0.2f, 0.0f}, n, 3);
    std::vector<double> observed(4, 0.0);
    for (const shared::float4& c : r.choice) {
        observed[static_cast<int>(c.x)] += 1.0;
    }
    std::vector<double> expected(4);
    for (int l = 0; l < 4; ++l) {
        expected[l] = n * power[l] / total;
    }
    const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
    EXPECT_GT(chi.p_value, 1e-4) << chi.summary();
}

// Sampling by area, for every triangle (the quad's triangles subtend more than the shipped rule's
// threshold from p, so the probe is built to sample every triangle by area).
TEST(LightSampling, AreaLightPointsAreUniformByAreaWithSolidAnglePdfs) {
    const Scene scene = light_scene();
    const glm::vec3 p(0.3f, -0.2f, 0.0f);
    const size_t n = 1 << 20;
    const ProbeResult r = probe(scene, p, n, 7, "-DRC_SOLID_ANGLE_SAMPLING_MIN=INFINITY");
    // The quad light spans x in [-0.5, 1.5], y in [-0.5, 0.5] at z = 2, normal -z.
    const int bins = 8;
    std::vector<double> observed(bins * bins, 0.0);
    size_t quad_samples = 0;
    const double selection = scene.lights.cdf[0];
    for (size_t i = 0; i < n; ++i) {
        if (static_cast<int>(r.choice[i].x) != 0) {
            continue;
        }
        ++quad_samples;
        const shared::float4& q = r.geometry[2 * i + 1];
        ASSERT_NEAR(q.z, 2.0f, 1e-4f);
        const int bx = std::min(bins - 1, static_cast<int>((q.x + 0.5f) / 2.0f * bins));
        const int by = std::min(bins - 1, static_cast<int>((q.y + 0.5f) * bins));
        observed[by * bins + bx] += 1.0;
        // pdf = P(select) * d^2 / (A cos(theta_light)), checked in double.
        const glm::dvec3 to(q.x - p.x, q.y - p.y, q.z - p.z);
        const double d2 = glm::dot(to, to);
        const double cosine = to.z / std::sqrt(d2);
        const double pdf = selection * d2 / (2.0 * cosine);
        EXPECT_NEAR(r.choice[i].y, pdf, 1e-4 * pdf);
        EXPECT_EQ(r.radiance[i].x, 4.0f);
        const glm::dvec3 direction(r.geometry[2 * i].x, r.geometry[2 * i].y, r.geometry[2 * i].z);
        EXPECT_NEAR(glm::dot(direction, to / std::sqrt(d2)), 1.0, 1e-5);
        if (::testing::Test::HasFailure()) {
            break;
        }
    }
    std::vector<double> expected(bins * bins, static_cast<double>(quad_samples) / (bins * bins));
    const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
    EXPECT_GT(chi.p_value, 1e-4) << chi.summary();
}

TEST(LightSampling, OneSidedAreaLightsGiveNothingBehind) {
    const Scene scene = light_scene();
    // Behind the quad (z > 2): every quad sample has zero pdf and radiance.
    const ProbeResult r = probe(scene, {0.3f, 0.1f, 4.0f}, 4096, 11);
    size_t quad = 0;
    for (size_t i = 0; i < r.choice.size(); ++i) {
        if (static_cast<int>(r.choice[i].x) == 0) {
            ++quad;
            EXPECT_EQ(r.choice[i].y, 0.0f);
        }
    }
    EXPECT_GT(quad, 100u);
}

TEST(LightSampling, PointAndSpotLightRadiance) {
    const Scene scene = light_scene();
    const size_t n = 4096;
    for (const glm::vec3& p : {glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f),
                               glm::vec3(1.5f, 0.0f, 0.0f), glm::vec3(3.0f, 0.0f, 0.0f)}) {
        const ProbeResult r = probe(scene, p, n, 5);
        const double spot_angle = std::atan2(p.x, 3.0) * 180.0 / kPi;  // from the spot axis
        const double spot_d2 = p.x * p.x + 9.0;
        const double falloff =
            spot_angle <= 20.0 ? 1.0 : (spot_angle >= 30.0 ? 0.0 : (30.0 - spot_angle) / 10.0);
        const double point_d2 = p.x * p.x + 9.0 + p.z * p.z;
        bool saw_point = false;
        bool saw_spot = false;
        for (size_t i = 0; i < n; ++i) {
            const int l = static_cast<int>(r.choice[i].x);
            if (l == 2) {
                saw_point = true;
                EXPECT_EQ(r.choice[i].z, 1.0f);  // delta
                EXPECT_NEAR(r.radiance[i].x, 2.0 / point_d2, 1e-5);
                EXPECT_NEAR(r.choice[i].y, scene.lights.cdf[2] - scene.lights.cdf[1], 1e-6);
            } else if (l == 3) {
                saw_spot = true;
                EXPECT_NEAR(r.radiance[i].x, 5.0 * falloff / spot_d2, 1e-4) << "x = " << p.x;
            }
        }
        EXPECT_TRUE(saw_point && saw_spot);
    }
}

// A distant light (travelling along unit d, irradiance E facing it): every sample of it is the
// direction -d whatever the point, delta (pdf = its selection probability) with a shadow ray
// without end, its radiance E; it is chosen in proportion to its power pi r^2 lum(E), r the
// scene's radius (half its bounding box's diagonal).
TEST(LightSampling, DistantLightIsADeltaDirectionWithoutEnd) {
    Scene scene = light_scene();
    Emitter sun;
    sun.name = "sun";
    sun.kind = EmitterKind::kDistant;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    sun.irradiance = {3.0f, 2.0f, 1.0f};
    scene.emitters.push_back(sun);
    scene.set_frame(0.0);
    ASSERT_EQ(scene.lights.lights.size(), 5u);
    const glm::vec3 low = scene.mesh.positions[0];
    glm::vec3 lo = low;
    glm::vec3 hi = low;
    for (const glm::vec3& v : scene.mesh.positions) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    const double r = 0.5 * glm::length(hi - lo);
    const double power[5] = {kPi * 2.0 * luminance({4, 2, 1}), kPi * 0.02 * 10.0, 4.0 * kPi * 2.0,
                             2.0 * kPi * (1.0 - std::cos(25.0 * kPi / 180.0)) * 5.0,
                             kPi * r * r * luminance({3, 2, 1})};
    const double total = power[0] + power[1] + power[2] + power[3] + power[4];
    const size_t n = 1 << 18;
    for (const glm::vec3 p : {glm::vec3(0.1f, 0.2f, 0.0f), glm::vec3(-3.0f, 5.0f, 1.0f)}) {
        const ProbeResult result = probe(scene, p, n, 11);
        size_t chosen = 0;
        for (size_t i = 0; i < n; ++i) {
            if (static_cast<int>(result.choice[i].x) != 4) {
                continue;
            }
            ++chosen;
            const shared::float4 d = result.geometry[2 * i];
            ASSERT_NEAR(d.x, -sun.direction.x, 1e-6f);
            ASSERT_NEAR(d.y, -sun.direction.y, 1e-6f);
            ASSERT_NEAR(d.z, -sun.direction.z, 1e-6f);
            ASSERT_NEAR(result.choice[i].y, power[4] / total, 1e-5);
            ASSERT_EQ(result.choice[i].z, 1.0f);  // delta
            ASSERT_EQ(result.choice[i].w, 1.0f);  // no end
            ASSERT_EQ(result.radiance[i].x, 3.0f);
            ASSERT_EQ(result.radiance[i].z, 1.0f);
        }
        const double expected = n * power[4] / total;
        EXPECT_NEAR(static_cast<double>(chosen), expected, 5.0 * std::sqrt(expected));
    }
}

// A scene whose only light is an environment map of `map` in `mapping` (a triangle under it).
Scene environment_scene(const Image& map, int mapping, const std::string& scratch) {
    const auto dir = test::scratch_dir(scratch);
    write_image(dir / "map.exr", map);
    Scene scene;
    scene.base_camera.position = {0, 0, -5};
    scene.base_camera.look_at = {0, 0, 0};
    Shape triangle;
    triangle.name = "triangle";
    triangle.type = "generated";
    triangle.mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    triangle.mesh.triangles = {{0, 1, 2}};
    scene.add_shape(triangle);
    Emitter sky;
    sky.name = "sky";
    load_environment_map(scene, sky, dir / "map.exr", disk_files(), glm::vec3(1.0f), mapping);
    scene.emitters.push_back(sky);
    scene.set_frame(0.0);
    return scene;
}

// A lat-long map (Mitsuba's convention: u = atan2(x, -z) / 2 pi, v = acos(y) / pi, the image's
// top row up): each texel is drawn in proportion to its mean radiance times its solid angle
// (chi-square over the texels, each sample's texel found from its direction by that definition),
// with the texel's radiance, and the pdf its probability over the solid angle its image area
// covers, p W H / (2 pi^2 sin theta).
TEST(LightSampling, EnvironmentMapTexelsInProportionToTheirPower) {
    const int width = 8;
    const int height = 4;
    Image map(width, height, 3);
    map.channel_names = {"R", "G", "B"};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                map.at(x, y, c) = 0.1f + static_cast<float>((x * 5 + y * 3 + c) % 7);
            }
        }
    }
    const Scene scene = environment_scene(map, RC_MAP_LATLONG, "light_sampling_latlong");
    std::vector<double> weight(width * height);
    double total = 0.0;
    for (int y = 0; y < height; ++y) {
        const double omega =
            2.0 * kPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
        for (int x = 0; x < width; ++x) {
            weight[y * width + x] =
                (map.at(x, y, 0) + map.at(x, y, 1) + map.at(x, y, 2)) / 3.0 * omega;
            total += weight[y * width + x];
        }
    }
    const size_t n = 1 << 18;
    const ProbeResult r = probe(scene, {0.1f, 0.2f, 0.3f}, n, 5);
    std::vector<double> observed(width * height, 0.0);
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 d(r.geometry[2 * i].x, r.geometry[2 * i].y, r.geometry[2 * i].z);
        double u = std::atan2(d.x, -d.z) / (2.0 * kPi);
        u -= std::floor(u);
        const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
        const int x = std::min(width - 1, static_cast<int>(u * width));
        const int y = std::min(height - 1, static_cast<int>(v * height));
        observed[y * width + x] += 1.0;
        ASSERT_EQ(r.choice[i].w, 1.0f);  // no end
        const double pdf =
            weight[y * width + x] / total * width * height / (2.0 * kPi * kPi * std::sin(v * kPi));
        // (theta from the direction's float y: near a pole acos amplifies its rounding, so the
        // density is compared away from them.)
        if (std::sin(v * kPi) > 0.05) {
            ASSERT_NEAR(r.choice[i].y, pdf, 1e-2 * pdf) << x << ", " << y;
        }
        ASSERT_EQ(r.radiance[i].x, map.at(x, y, 0)) << x << ", " << y;
        ASSERT_EQ(r.radiance[i].z, map.at(x, y, 2)) << x << ", " << y;
    }
    std::vector<double> expected(width * height);
    for (size_t t = 0; t < expected.size(); ++t) {
        expected[t] = n * weight[t] / total;
    }
    const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
    EXPECT_GT(chi.p_value, 1e-4) << chi.summary();
}

// An equal-area map (pbrt-v4's) of one radiance is the constant environment: every sample's pdf
// 1 / 4 pi, the directions uniform on the sphere (chi-square over 8 bands of z and 8 sectors of
// the azimuth, both uniform for the uniform density whatever the mapping).
TEST(LightSampling, ConstantEqualAreaMapIsUniformOnTheSphere) {
    Image map(4, 4, 3);
    map.channel_names = {"R", "G", "B"};
    std::fill(map.pixels.begin(), map.pixels.end(), 2.0f);
    const Scene scene = environment_scene(map, RC_MAP_EQUAL_AREA, "light_sampling_equal_area");
    const size_t n = 1 << 18;
    const ProbeResult r = probe(scene, {0.0f, 0.0f, 0.5f}, n, 9);
    std::vector<double> bands(8, 0.0);
    std::vector<double> sectors(8, 0.0);
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 d(r.geometry[2 * i].x, r.geometry[2 * i].y, r.geometry[2 * i].z);
        ASSERT_NEAR(glm::length(d), 1.0, 1e-5);
        ASSERT_NEAR(r.choice[i].y, 1.0 / (4.0 * kPi), 1e-4 / (4.0 * kPi));
        ASSERT_EQ(r.radiance[i].y, 2.0f);
        bands[std::min(7, static_cast<int>((d.z + 1.0) * 4.0))] += 1.0;
        double phi = std::atan2(d.y, d.x) / (2.0 * kPi);
        phi -= std::floor(phi);
        sectors[std::min(7, static_cast<int>(phi * 8.0))] += 1.0;
    }
    const std::vector<double> expected(8, n / 8.0);
    EXPECT_GT(test::chi_square_test(bands, expected).p_value, 1e-4);
    EXPECT_GT(test::chi_square_test(sectors, expected).p_value, 1e-4);
}

}  // namespace
}  // namespace rc
