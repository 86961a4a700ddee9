// Every registered method (host/methods/registry.h, iterated: no list of methods here) renders
// analytic scenes through the command line at 16 x 16, and its image is checked against their
// closed forms:
// - the furnace of test::furnace_box: a closed box with a block floating in it, every surface
//   diffuse with reflectance rho and emitting Le. A path of at most D bounces gathers
//   Le (1 + rho + ... + rho^D) whatever the geometry, so every pixel shows that radiance;
// - a diffuse plane of reflectance rho under a constant sky of radiance L, nothing else: its
//   irradiance is pi L, so it reflects rho L towards the camera, channel by channel;
// - a smooth glass sphere, a thin pane and a near-perfect mirror under the sky alone: lossless
//   interfaces in a furnace, so every pixel shows the sky's radiance L;
// - the plane under a distant light instead (rho / pi E cos theta), and an L of two planes under
//   it, against the path tracer at many samples (the interreflection).
// Every image has exactly the layers its method declares (MethodEntry::aovs). A method whose
// beauty is radiance (MethodEntry::beauty) has the analytic mean in each channel; a declared
// albedo layer shows rho; a declared normal layer shows the plane's normal. The normals preview
// shows in every pixel the encoding of one of the scene's face normals. A method that declares
// --temporal also renders the furnace over two frames with it, each at the furnace's radiance.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"
#include "methods/registry.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr int kSize = 16;
constexpr int kSpp = 32;
// The path depth limit, deep enough that how a method counts it does not show (the furnace's
// next bounce is rho^65 of its radiance): with a limit of 3, ivg-gather and the decomposition
// show one bounce more (a grid read at a hit allows one more, docs/irradiance-vector-grid.md).
constexpr int kMaxDepth = 64;

// The sky scene: a grey plane seen from straight above, filling the image, under a coloured sky.
constexpr float kPlaneReflectance = 0.5f;
constexpr std::array<float, 3> kSky = {1.0f, 0.5f, 0.25f};

// Bound on each channel's mean over the image relative to the analytic radiance. The path
// tracer's mean of 16 x 16 pixels at 32 samples has a standard error of 0.6 % of the furnace's
// radiance and 0.3 % of the sky plane's (measured from the pixels' spread), so 3 % is 5 standard
// errors; the caching methods' interpolation errors average out over a scene whose irradiance is
// uniform (measured within 0.2 % of both at these settings). Losing bounces beyond the k-th
// takes rho^(k+1) / (1 - rho) Le, more than 3 % of the furnace for every k up to 5; losing the
// sky, or counting it twice (a hit and a light sample), is all of the plane's radiance.
constexpr double kMeanTolerance = 0.03;

bool has_layer(const MethodEntry& method, const std::string& layer) {
    return std::find(method.aovs.begin(), method.aovs.end(), layer) != method.aovs.end();
}

std::string test_name(const std::string& method) {
    std::string name = method;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

std::vector<std::string> registered_methods() {
    std::vector<std::string> names;
    for (const MethodEntry& method : method_registry()) {
        names.push_back(method.name);
    }
    return names;
}

// A grey plane seen from straight above, filling the image, under `emitter` (a JSON object),
// written to the scratch folder `scratch`.
std::filesystem::path plane_scene(const std::string& scratch, const std::string& emitter) {
    const auto dir = test::scratch_dir(scratch);
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 30,
                   "resolution": [16, 16]},
        "materials": {"ground": {"type": "diffuse", "reflectance": )"
                                      << kPlaneReflectance << R"(}},
        "shapes": [{"type": "rectangle", "material": "ground",
                    "transform": [{"scale": 5}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]}],
        "emitters": [)" << emitter << "]}";
    return dir / "scene.json";
}

std::string rgb_json(const std::array<float, 3>& c) {
    return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
           "]";
}

std::filesystem::path sky_plane_scene(const std::string& scratch) {
    return plane_scene(scratch, R"({"type": "constant", "radiance": )" + rgb_json(kSky) + "}");
}

// The distant-light scenes: the sky scene's plane under a distant light 60 degrees from its
// normal, of irradiance kSun on a surface facing it (the plane's irradiance kSun cos 60, its
// radiance rho / pi of that); and an L of a floor and a wall, where 18 % of what the camera sees
// is light the wall and floor reflect onto each other.
constexpr std::array<float, 3> kSun = {2.0f, 1.0f, 0.5f};

std::filesystem::path distant_plane_scene(const std::string& scratch) {
    return plane_scene(scratch,
                       R"({"type": "distant", "direction": [0.8660254, -0.5, 0], "irradiance": )" +
                           rgb_json(kSun) + "}");
}

std::filesystem::path distant_corner_scene(const std::string& scratch) {
    const auto dir = test::scratch_dir(scratch);
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 4, 6], "look_at": [0, 0.5, 0], "up": [0, 1, 0], "fov": 40,
                   "resolution": [16, 16]},
        "materials": {"grey": {"type": "diffuse", "reflectance": 0.7}},
        "shapes": [{"type": "rectangle", "material": "grey",
                    "transform": [{"scale": 4}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]},
                   {"type": "rectangle", "material": "grey",
                    "transform": [{"scale": 4}, {"translate": [0, 4, -4]}]}],
        "emitters": [{"type": "distant", "direction": [0.3, -0.6, -0.74],
                      "irradiance": [3, 2, 1]}]
    })";
    return dir / "scene.json";
}

// The sky scene's plane under a lat-long environment map of kMapWidth x kMapHeight texels of
// varied radiance (the top row looks up +y, the plane's normal). The plane's irradiance is the
// sum over the upper half's texels of L times the integral of cos(theta) over the texel,
// (pi / W) (sin^2 theta1 - sin^2 theta0) for a texel of row theta0..theta1: its radiance rho / pi
// of that. A map sampled or looked up in the wrong place, or the wrong density, shows.
constexpr int kMapWidth = 8;
constexpr int kMapHeight = 6;

float map_texel(int x, int y, int c) {
    return 0.2f + 0.5f * static_cast<float>((x * 7 + y * 3 + c * 5) % 11);
}

std::filesystem::path environment_map_scene(const std::string& scratch) {
    const std::filesystem::path scene =
        plane_scene(scratch, R"({"type": "envmap", "filename": "sky.exr"})");
    Image map(kMapWidth, kMapHeight, 3);
    map.channel_names = {"R", "G", "B"};
    for (int y = 0; y < kMapHeight; ++y) {
        for (int x = 0; x < kMapWidth; ++x) {
            for (int c = 0; c < 3; ++c) {
                map.at(x, y, c) = map_texel(x, y, c);
            }
        }
    }
    write_image(scene.parent_path() / "sky.exr", map);
    return scene;
}

std::array<double, 3> environment_map_plane_radiance() {
    const double pi = 3.14159265358979;
    std::array<double, 3> irradiance = {0.0, 0.0, 0.0};
    for (int y = 0; y < kMapHeight / 2; ++y) {
        const double s0 = std::sin(pi * y / kMapHeight);
        const double s1 = std::sin(pi * (y + 1) / kMapHeight);
        for (int x = 0; x < kMapWidth; ++x) {
            for (int c = 0; c < 3; ++c) {
                irradiance[c] += map_texel(x, y, c) * pi / kMapWidth * (s1 * s1 - s0 * s0);
            }
        }
    }
    for (double& e : irradiance) {
        e *= kPlaneReflectance / pi;
    }
    return irradiance;
}

// Renders `scene` with `method` at kSize x kSize into EXRs of every layer, one per frame of
// `frames` (render --frames A:B) after `options`: kSpp samples per pixel, one for the normals
// preview (its one centred ray per pixel sees one face). Empty where the render failed.
std::vector<Image> render(const MethodEntry& method, const std::filesystem::path& scene,
                          const std::string& scratch, int frames = 1,
                          const std::vector<std::string>& options = {}) {
    const int spp = method.beauty == Beauty::kNormalPreview ? 1 : kSpp;
    const auto dir = test::scratch_dir(scratch);
    std::vector<std::string> args = {"render",   scene.string(),
                                     "-o",       (dir / "f####.exr").string(),
                                     "--frames", "0:" + std::to_string(frames - 1),
                                     "--method", method.name,
                                     "--width",  std::to_string(kSize),
                                     "--height", std::to_string(kSize),
                                     "--spp",    std::to_string(spp),
                                     "-D",       "max_depth=" + std::to_string(kMaxDepth),
                                     "-q"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CommandResult result = test::run_radcache(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    std::vector<Image> images;
    for (int frame = 0; result.exit_code == 0 && frame < frames; ++frame) {
        char name[16];
        std::snprintf(name, sizeof(name), "f%04d.exr", frame);
        images.push_back(read_image(dir / name));
    }
    return images;
}

double furnace_radiance() {
    double radiance = 0.0;
    for (int bounce = 0; bounce <= kMaxDepth; ++bounce) {
        radiance += test::kFurnaceEmission * std::pow(test::kFurnaceReflectance, bounce);
    }
    return radiance;
}

void expect_declared_layers(const MethodEntry& method, const Image& image) {
    const std::vector<std::string> layers = layer_names(image);
    EXPECT_EQ(std::set<std::string>(layers.begin(), layers.end()),
              std::set<std::string>(method.aovs.begin(), method.aovs.end()));
}

// Each channel's mean over the image.
std::array<double, 3> channel_means(const Image& layer) {
    std::array<double, 3> sum = {0.0, 0.0, 0.0};
    for (int y = 0; y < layer.height; ++y) {
        for (int x = 0; x < layer.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                sum[c] += layer.at(x, y, c);
            }
        }
    }
    for (double& s : sum) {
        s /= static_cast<double>(layer.width) * layer.height;
    }
    return sum;
}

void expect_radiance(const MethodEntry& method, const Image& image,
                     const std::array<double, 3>& expected) {
    const Image beauty = select_layers(image, {"beauty"});
    for (float v : beauty.pixels) {
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << v;
    }
    const std::array<double, 3> mean = channel_means(beauty);
    std::printf("%s: beauty mean (%.4f, %.4f, %.4f), expected (%.4f, %.4f, %.4f)\n",
                method.name.c_str(), mean[0], mean[1], mean[2], expected[0], expected[1],
                expected[2]);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(mean[c], expected[c], kMeanTolerance * expected[c]) << "channel " << c;
    }
}

// Every pixel of the albedo layer is `rho`: every surface the camera sees has that reflectance.
void expect_albedo(const Image& image, float rho) {
    const Image albedo = select_layers(image, {"albedo"});
    for (float v : albedo.pixels) {
        ASSERT_NEAR(v, rho, 1e-5f);
    }
}

// The normals preview's pixel (n + 1) / 2 s with s = 0.25 + 0.75 |cos| in [0.25, 1]: for a normal
// n along an axis, two channels are s / 2 and the third 0 or s. Returns that normal, or a zero
// vector for any other pixel.
std::array<int, 3> preview_axis_normal(const Image& beauty, int x, int y) {
    const std::array<float, 3> c = {beauty.at(x, y, 0), beauty.at(x, y, 1), beauty.at(x, y, 2)};
    for (int axis = 0; axis < 3; ++axis) {
        const float half_s = c[(axis + 1) % 3];
        if (std::abs(c[(axis + 2) % 3] - half_s) > 1e-5f || half_s < 0.125f - 1e-6f ||
            half_s > 0.5f + 1e-6f) {
            continue;
        }
        std::array<int, 3> n = {0, 0, 0};
        if (std::abs(c[axis] - 2.0f * half_s) <= 1e-5f) {
            n[axis] = 1;
            return n;
        }
        if (std::abs(c[axis]) <= 1e-6f) {
            n[axis] = -1;
            return n;
        }
    }
    return {0, 0, 0};
}

class EveryMethod : public testing::TestWithParam<std::string> {
   protected:
    const MethodEntry& method() const { return find_method(GetParam()); }
};

// The furnace box: Le (1 + rho + ... + rho^D) in every pixel; the preview sees only the box's
// and the block's faces, whose normals lie along the axes.
TEST_P(EveryMethod, FurnaceShowsItsAnalyticRadiance) {
    const MethodEntry& entry = method();
    const std::string scratch = "every_method_furnace_" + test_name(entry.name);
    const std::vector<Image> images =
        render(entry, test::furnace_box(scratch).path, scratch + "_out");
    ASSERT_EQ(images.size(), 1u);
    const Image& image = images[0];
    expect_declared_layers(entry, image);
    const double radiance = furnace_radiance();
    switch (entry.beauty) {
        case Beauty::kRadiance:
            expect_radiance(entry, image, {radiance, radiance, radiance});
            if (has_layer(entry, "albedo")) {
                expect_albedo(image, test::kFurnaceReflectance);
            }
            break;
        case Beauty::kNormalPreview: {
            const Image beauty = select_layers(image, {"beauty"});
            int axis_pixels = 0;
            for (int y = 0; y < beauty.height; ++y) {
                for (int x = 0; x < beauty.width; ++x) {
                    const std::array<int, 3> n = preview_axis_normal(beauty, x, y);
                    axis_pixels += std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
                }
            }
            EXPECT_EQ(axis_pixels, beauty.width * beauty.height);
            break;
        }
    }
}

// A method that caches across frames (it declares --temporal) shows the furnace's radiance in
// every frame of a temporal render: records kept from frame to frame keep their light.
TEST_P(EveryMethod, TemporalFurnaceShowsItsAnalyticRadianceEveryFrame) {
    const MethodEntry& entry = method();
    if (!test::declares(entry, "--temporal")) {
        GTEST_SKIP() << entry.name << " does not declare --temporal";
    }
    const std::string scratch = "every_method_temporal_" + test_name(entry.name);
    const std::vector<Image> images =
        render(entry, test::furnace_box(scratch).path, scratch + "_out", 2, {"--temporal"});
    ASSERT_EQ(images.size(), 2u);
    const double radiance = furnace_radiance();
    for (const Image& image : images) {
        expect_declared_layers(entry, image);
        expect_radiance(entry, image, {radiance, radiance, radiance});
    }
}

// The plane under the sky: rho L in each channel; the preview shows the plane's normal, up, in
// every pixel.
TEST_P(EveryMethod, PlaneUnderConstantSkyReflectsAlbedoTimesSky) {
    const MethodEntry& entry = method();
    const std::string scratch = "every_method_sky_" + test_name(entry.name);
    const std::vector<Image> images = render(entry, sky_plane_scene(scratch), scratch + "_out");
    ASSERT_EQ(images.size(), 1u);
    const Image& image = images[0];
    expect_declared_layers(entry, image);
    switch (entry.beauty) {
        case Beauty::kRadiance:
            expect_radiance(entry, image,
                            {kPlaneReflectance * kSky[0], kPlaneReflectance * kSky[1],
                             kPlaneReflectance * kSky[2]});
            if (has_layer(entry, "albedo")) {
                expect_albedo(image, kPlaneReflectance);
            }
            if (has_layer(entry, "normal")) {
                const Image normal = select_layers(image, {"normal"});
                for (int y = 0; y < normal.height; ++y) {
                    for (int x = 0; x < normal.width; ++x) {
                        EXPECT_NEAR(normal.at(x, y, 0), 0.0f, 1e-5f);
                        EXPECT_NEAR(normal.at(x, y, 1), 1.0f, 1e-5f);
                        EXPECT_NEAR(normal.at(x, y, 2), 0.0f, 1e-5f);
                    }
                }
            }
            break;
        case Beauty::kNormalPreview: {
            const Image beauty = select_layers(image, {"beauty"});
            for (int y = 0; y < beauty.height; ++y) {
                for (int x = 0; x < beauty.width; ++x) {
                    EXPECT_EQ(preview_axis_normal(beauty, x, y), (std::array<int, 3>{0, 1, 0}))
                        << x << ", " << y;
                }
            }
            break;
        }
    }
}

// The plane under the distant light: rho / pi E cos 60 in each channel, exactly but for
// rounding (a delta light's one sample per point is its whole direct light, and nothing else
// lights the plane); a light sampled in the wrong direction, or counted as the environment,
// shows as a wrong or missing cosine.
TEST_P(EveryMethod, PlaneUnderDistantLightReflectsAlbedoTimesIrradianceCosine) {
    const MethodEntry& entry = method();
    if (entry.beauty != Beauty::kRadiance) {
        GTEST_SKIP() << entry.name << " shows no radiance";
    }
    const std::string scratch = "every_method_distant_" + test_name(entry.name);
    const std::vector<Image> images = render(entry, distant_plane_scene(scratch), scratch + "_out");
    ASSERT_EQ(images.size(), 1u);
    const double pi = 3.14159265358979;
    const double factor = kPlaneReflectance / pi * 0.5;
    expect_radiance(entry, images[0], {factor * kSun[0], factor * kSun[1], factor * kSun[2]});
}

// The floor and wall under the distant light: each channel's mean within 2 % of the path
// tracer's at 1 024 samples (its standard error there 0.1 %; the caching methods measured within
// 0.5 %), so within 11 % on the 18 % that is interreflection: photons, records and the grid's
// sources must carry the distant light's power (pi r^2 E over the scene's disk) into the bounce.
TEST_P(EveryMethod, DistantLightInterreflectionMatchesThePathTracer) {
    const MethodEntry& entry = method();
    if (entry.beauty != Beauty::kRadiance) {
        GTEST_SKIP() << entry.name << " shows no radiance";
    }
    const std::string scratch = "every_method_distant_corner_" + test_name(entry.name);
    const std::filesystem::path scene = distant_corner_scene(scratch);
    const auto ref_dir = test::scratch_dir(scratch + "_ref");
    const test::CommandResult reference = test::run_radcache(
        {"render", scene.string(), "-o", (ref_dir / "ref.exr").string(), "--method", "pt", "--spp",
         "1024", "-D", "max_depth=" + std::to_string(kMaxDepth), "-q"});
    ASSERT_EQ(reference.exit_code, 0) << reference.output;
    const std::array<double, 3> expected =
        channel_means(select_layers(read_image(ref_dir / "ref.exr"), {"beauty"}));
    const std::vector<Image> images = render(entry, scene, scratch + "_out");
    ASSERT_EQ(images.size(), 1u);
    const std::array<double, 3> mean = channel_means(select_layers(images[0], {"beauty"}));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(mean[c], expected[c], 0.02 * expected[c]) << "channel " << c;
    }
}

TEST_P(EveryMethod, PlaneUnderEnvironmentMapReflectsItsIrradiance) {
    const MethodEntry& entry = method();
    if (entry.beauty != Beauty::kRadiance) {
        GTEST_SKIP() << entry.name << " shows no radiance";
    }
    const std::string scratch = "every_method_envmap_" + test_name(entry.name);
    const std::vector<Image> images =
        render(entry, environment_map_scene(scratch), scratch + "_out");
    ASSERT_EQ(images.size(), 1u);
    expect_radiance(entry, images[0], environment_map_plane_radiance());
}

// The specular furnace: a smooth glass sphere (index 1.5), a thin glass pane and a conductor of
// reflectance 0.9999 under the sky of radiance kSky, nothing else. Every interface is lossless
// (Fresnel reflection and refraction sum to 1; the mirror loses 1e-4), so every pixel shows the
// sky: light lost at an interface, refraction's radiance scaling applied once only, or a delta
// lobe weighted by MIS shows as a darker or brighter mean.
std::filesystem::path specular_furnace_scene(const std::string& scratch) {
    const auto dir = test::scratch_dir(scratch);
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 0, 6], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 30,
                   "resolution": [16, 16]},
        "materials": {"glass": {"type": "dielectric", "ior": 1.5},
                      "pane": {"type": "thindielectric", "ior": 1.5},
                      "mirror": {"type": "conductor", "reflectance": 0.9999}},
        "shapes": [{"type": "sphere", "material": "glass", "radius": 1},
                   {"type": "rectangle", "material": "pane",
                    "transform": [{"scale": 0.8}, {"translate": [1.0, 0.8, 2]}]},
                   {"type": "rectangle", "material": "mirror",
                    "transform": [{"scale": 1.2}, {"rotate": {"axis": [0, 1, 0], "angle": 35}},
                                  {"translate": [-1.2, -1.0, -1.5]}]}],
        "emitters": [{"type": "constant", "radiance": )"
                                      << rgb_json(kSky) << "}]}";
    return dir / "scene.json";
}

TEST_P(EveryMethod, SpecularFurnaceShowsTheSky) {
    const MethodEntry& entry = method();
    if (entry.beauty != Beauty::kRadiance) {
        GTEST_SKIP() << entry.name << " shows no radiance";
    }
    const std::string scratch = "every_method_specular_" + test_name(entry.name);
    const std::vector<Image> images =
        render(entry, specular_furnace_scene(scratch), scratch + "_out");
    ASSERT_EQ(images.size(), 1u);
    expect_radiance(entry, images[0], {kSky[0], kSky[1], kSky[2]});
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryMethod, testing::ValuesIn(registered_methods()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             return test_name(info.param);
                         });

}  // namespace
}  // namespace rc
