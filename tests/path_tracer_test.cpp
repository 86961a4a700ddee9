// The reference path tracer against analytic answers (the furnace, a plane under a constant
// sky), against its stored Cornell-box reference by a per-pixel statistical test, and for
// determinism and AOV consistency.
#include "methods/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "image/image_io.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

namespace rc {
namespace {

struct Render {
    Image image;
    PathTracerStats stats;
};

Render render(const Scene& scene, PathTracerOptions options, Context& context) {
    const Bvh bvh = build_bvh(scene.mesh);
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    PathTracer tracer(context, scene, device_bvh, device_scene);
    Render r;
    r.image = tracer.render(options, &r.stats);
    return r;
}

Render render(const Scene& scene, PathTracerOptions options) {
    return render(scene, std::move(options), test::shared_context());
}

// Mean of channel c over the image and the standard error of that mean (from the variance
// layer, channels 15..17).
std::pair<double, double> mean_and_error(const Image& image, int c) {
    double sum = 0.0;
    double variance = 0.0;
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    for (size_t p = 0; p < pixels; ++p) {
        sum += image.pixels[p * image.channels + c];
        variance += image.pixels[p * image.channels + 15 + c];
    }
    return {sum / pixels, std::sqrt(variance) / pixels};
}

Scene furnace() { return load_scene(test::source_dir() / "scenes/furnace/scene.json"); }

// Le / (1 - rho) = 0.5 / 0.25 = 2 everywhere; within 1%, with the standard error small enough
// (below 0.2%) that 1% is more than 5 standard errors.
TEST(PathTracer, FurnaceRadianceIsEmissionOverOneMinusAlbedo) {
    PathTracerOptions options;
    options.width = 32;
    options.height = 32;
    options.spp = 128;
    options.seed = 5;
    options.max_depth = 1000;
    const Render r = render(furnace(), options);
    EXPECT_EQ(r.stats.nonfinite_samples, 0u);
    for (float v : r.image.pixels) {
        ASSERT_TRUE(std::isfinite(v));
    }
    for (int c = 0; c < 3; ++c) {
        const auto [mean, error] = mean_and_error(r.image, c);
        EXPECT_NEAR(mean, 2.0, 0.02) << "channel " << c << ", standard error " << error;
        EXPECT_LT(error, 0.004);
    }
}

// With at most k bounces the furnace shows Le (1 + rho + ... + rho^k): exactly Le for k = 0.
TEST(PathTracer, MaxDepthCountsBounces) {
    const Scene scene = furnace();
    for (int depth : {0, 1, 3}) {
        PathTracerOptions options;
        options.width = 16;
        options.height = 16;
        options.spp = 64;
        options.max_depth = depth;
        const Render r = render(scene, options);
        double expected = 0.0;
        for (int i = 0; i <= depth; ++i) {
            expected += 0.5 * std::pow(0.75, i);
        }
        const auto [mean, error] = mean_and_error(r.image, 0);
        if (depth == 0) {
            EXPECT_DOUBLE_EQ(mean, 0.5);
        } else {
            EXPECT_NEAR(mean, expected, 5.0 * error + 1e-6) << "max depth " << depth;
        }
    }
}

// A diffuse plane of albedo rho under a constant environment of radiance L has irradiance pi L,
// so it reflects rho L towards the camera.
TEST(PathTracer, DiffusePlaneUnderConstantSkyReflectsAlbedoTimesRadiance) {
    const auto dir = test::scratch_dir("sky_plane");
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 30,
                   "resolution": [24, 24]},
        "materials": {"ground": {"type": "diffuse", "reflectance": 0.6}},
        "shapes": [{"type": "rectangle", "material": "ground",
                    "transform": [{"scale": 1000}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]}],
        "emitters": [{"type": "constant", "radiance": [1.0, 0.5, 0.25]}]
    })";
    const Scene scene = load_scene(dir / "scene.json");
    PathTracerOptions options;
    options.spp = 256;
    const Render r = render(scene, options);
    const double radiance[3] = {1.0, 0.5, 0.25};
    for (int c = 0; c < 3; ++c) {
        const auto [mean, error] = mean_and_error(r.image, c);
        EXPECT_NEAR(mean, 0.6 * radiance[c], 0.01 * 0.6 * radiance[c])
            << "channel " << c << ", standard error " << error;
        EXPECT_LT(5.0 * error, 0.01 * 0.6 * radiance[c]);
    }
}

// beauty = direct + indirect per pixel; albedo and normal describe the first hit.
TEST(PathTracer, AovsAreConsistent) {
    PathTracerOptions options;
    options.width = 16;
    options.height = 16;
    options.spp = 8;
    const Render r = render(furnace(), options);
    const size_t pixels = 16 * 16;
    for (size_t p = 0; p < pixels; ++p) {
        const float* px = &r.image.pixels[p * 18];
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(px[c], px[3 + c] + px[6 + c], 1e-5f * (1.0f + px[c]));
            EXPECT_FLOAT_EQ(px[9 + c], 0.75f);  // albedo
        }
        // The mean of the unit normals seen within the pixel (on a 16 x 16 view of a sphere they
        // turn by a few degrees across a pixel).
        const float length = std::sqrt(px[12] * px[12] + px[13] * px[13] + px[14] * px[14]);
        EXPECT_GT(length, 0.99f);
        EXPECT_LT(length, 1.0f + 1e-5f);
    }
    EXPECT_EQ(r.image.channel_names[0], "R");
    EXPECT_EQ(r.image.channel_names[6], "indirect.R");
    EXPECT_EQ(r.image.channel_names[15], "variance.R");
}

// A sample that is NaN or infinite is counted, reported with its pixel, and left out of the
// image (a material with a NaN reflectance, which the loader would refuse, makes every one so).
TEST(PathTracer, NonFiniteSamplesAreCountedAndDropped) {
    Scene scene = furnace();
    scene.materials[0].diffuse = glm::vec3(std::nanf(""), 0.5f, 0.5f);
    PathTracerOptions options;
    options.width = 8;
    options.height = 8;
    options.spp = 3;
    const Render r = render(scene, options);
    EXPECT_EQ(r.stats.nonfinite_samples, 8u * 8u * 3u);
    EXPECT_EQ(r.stats.first_nonfinite_pixel, 0);
    for (float v : r.image.pixels) {
        ASSERT_TRUE(std::isfinite(v));
    }
}

bool bitwise_equal(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(PathTracer, SameSeedGivesBitwiseIdenticalPixelsWhateverTheChunking) {
    const Scene scene = test::load_cornell_box();
    PathTracerOptions options;
    options.width = 40;
    options.height = 30;
    options.spp = 4;
    options.seed = 77;
    const Render a = render(scene, options);
    const Render b = render(scene, options);
    EXPECT_TRUE(bitwise_equal(a.image, b.image));
    EXPECT_EQ(a.stats.rays, b.stats.rays);
    ContextOptions small = test::default_context_options();
    small.local_size = 8;
    small.max_chunk_items = 100;
    Context chunked(small);
    EXPECT_TRUE(bitwise_equal(a.image, render(scene, options, chunked).image));
    options.seed = 78;
    EXPECT_FALSE(bitwise_equal(a.image, render(scene, options).image));
}

}  // namespace
}  // namespace rc
