// The reference path tracer against analytic answers (the furnace, a plane under a constant
// sky), against its stored Cornell-box reference by a per-pixel statistical test, and for
// determinism and AOV consistency.
#include "methods/path_tracer/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "image/image_io.h"
#include "image_options.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

struct Render {
    Image image;
    PathTracerStats stats;
};

Render render(const Scene& scene, PathTracerOptions options, Context& context) {
    const Bvh bvh = build_bvh(scene.mesh, context.bvh_layout());
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    PathTracer tracer({context, scene, device_bvh, device_scene});
    Render r;
    r.image = tracer.render(options, &r.stats);
    return r;
}

Render render(const Scene& scene, PathTracerOptions options) {
    return render(scene, std::move(options), test::shared_context());
}

// Mean of channel c over an image of `spp` samples per pixel and the standard error of that mean
// (from the stddev layer, channels 15..17).
std::pair<double, double> mean_and_error(const Image& image, int c, int spp) {
    double sum = 0.0;
    double variance = 0.0;
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    for (size_t p = 0; p < pixels; ++p) {
        sum += image.pixels[p * image.channels + c];
        const double deviation = image.pixels[p * image.channels + 15 + c];
        variance += deviation * deviation / spp;
    }
    return {sum / pixels, std::sqrt(variance) / pixels};
}

Scene furnace() { return load_scene(test::source_dir() / "scenes/furnace/scene.json"); }

// Le / (1 - rho) = 0.5 / 0.25 = 2 everywhere; within 1%, with the standard error small enough
// (below 0.2%) that 1% is more than 5 standard errors.
TEST(PathTracer, FurnaceRadianceIsEmissionOverOneMinusAlbedo) {
    auto options = test::image_options<PathTracerOptions>(32, 32, 128, 5);
    options.max_depth = 1000;
    const Render r = render(furnace(), options);
    EXPECT_EQ(r.stats.nonfinite_samples, 0u);
    for (float v : r.image.pixels) {
        ASSERT_TRUE(std::isfinite(v));
    }
    for (int c = 0; c < 3; ++c) {
        const auto [mean, error] = mean_and_error(r.image, c, options.spp);
        EXPECT_NEAR(mean, 2.0, 0.02) << "channel " << c << ", standard error " << error;
        EXPECT_LT(error, 0.004);
    }
}

// With at most k bounces the furnace shows Le (1 + rho + ... + rho^k): exactly Le for k = 0.
TEST(PathTracer, MaxDepthCountsBounces) {
    const Scene scene = furnace();
    for (int depth : {0, 1, 3}) {
        auto options = test::image_options<PathTracerOptions>(16, 16, 64);
        options.max_depth = depth;
        const Render r = render(scene, options);
        double expected = 0.0;
        for (int i = 0; i <= depth; ++i) {
            expected += 0.5 * std::pow(0.75, i);
        }
        const auto [mean, error] = mean_and_error(r.image, 0, options.spp);
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
        const auto [mean, error] = mean_and_error(r.image, c, options.spp);
        EXPECT_NEAR(mean, 0.6 * radiance[c], 0.01 * 0.6 * radiance[c])
            << "channel " << c << ", standard error " << error;
        EXPECT_LT(5.0 * error, 0.01 * 0.6 * radiance[c]);
    }
}

// beauty = direct + indirect per pixel; albedo and normal describe the first hit.
TEST(PathTracer, AovsAreConsistent) {
    auto options = test::image_options<PathTracerOptions>(16, 16, 8);
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
    EXPECT_EQ(r.image.channel_names[15], "stddev.R");
}

// A sample that is NaN or infinite is counted, reported with its pixel, and left out of the
// image (a material with a NaN reflectance, which the loader would refuse, makes every one so).
TEST(PathTracer, NonFiniteSamplesAreCountedAndDropped) {
    Scene scene = furnace();
    scene.materials[0].diffuse = glm::vec3(std::nanf(""), 0.5f, 0.5f);
    auto options = test::image_options<PathTracerOptions>(8, 8, 3);
    const Render r = render(scene, options);
    EXPECT_EQ(r.stats.nonfinite_samples, 8u * 8u * 3u);
    EXPECT_EQ(r.stats.first_nonfinite_pixel, 0);
    for (float v : r.image.pixels) {
        ASSERT_TRUE(std::isfinite(v));
    }
}

int channel_index(const Image& image, const std::string& name) {
    for (int c = 0; c < image.channels; ++c) {
        if (image.channel_names[c] == name) {
            return c;
        }
    }
    ADD_FAILURE() << "no channel " << name;
    return 0;
}

// Variance of rounding a value to half precision (uniform over one half ulp).
double half_rounding_variance(double value) {
    const double magnitude = std::max(std::fabs(value), 6.1e-5);  // the smallest normal half
    const double ulp = std::ldexp(1.0, static_cast<int>(std::floor(std::log2(magnitude))) - 10);
    return ulp * ulp / 12.0;
}

// The stored reference (scenes/cornell-box/reference.exr, 512^2 at the samples per pixel its
// reference.json states, 65 536, with each pixel's per-sample standard deviation) box-filtered
// 4 x 4 is the expected value of a 128^2 render.
// Per pixel and channel z = (render - reference) / sqrt(var_render + var_reference + var_half),
// where var_render, the variance of the render's 128-sample mean, comes from the reference's
// per-sample variance (16 x 65 536 samples per test pixel) rather than from the render's own 128
// samples: skewed pixels (rare bright paths) underestimate their variance from few samples.
// Beyond |z| = 5 a normal variable lies with probability 6e-7; means of 128 skewed samples (rare
// bright paths) are not quite normal and fall short more often, so the test allows 0.1% of the
// 49 152 values beyond 5 (15 on the shipped reference; 16 on the 4096-spp one before), and
// checks the image-wide sum of differences against its standard deviation (|Z| < 5) for a
// global bias.
TEST(PathTracer, CornellBoxAgreesWithItsReferenceByPerPixelZTest) {
    const std::filesystem::path folder = test::source_dir() / "scenes/cornell-box";
    const Image reference = read_image(folder / "reference.exr");
    const double reference_spp =
        nlohmann::json::parse(read_file(folder / "reference.json"))["spp"].get<double>();
    const int factor = 4;
    const int width = reference.width / factor;
    const int height = reference.height / factor;
    auto options = test::image_options<PathTracerOptions>(width, height, 128, 12345);
    const Render r = render(test::load_cornell_box(), options);
    EXPECT_EQ(r.stats.nonfinite_samples, 0u);
    size_t outliers = 0;
    size_t values = 0;
    for (int c = 0; c < 3; ++c) {
        const std::string channel(1, "RGB"[c]);
        const int ref_c = channel_index(reference, channel);
        const int ref_deviation = channel_index(reference, "stddev." + channel);
        const int test_c = channel_index(r.image, channel);
        const int ref_indirect = channel_index(reference, "indirect." + channel);
        const int test_indirect = channel_index(r.image, "indirect." + channel);
        double sum_difference = 0.0;
        double sum_variance = 0.0;
        double indirect_reference = 0.0;
        double indirect_render = 0.0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                double mean = 0.0;
                double mean_square = 0.0;
                double within = 0.0;  // mean per-sample variance of the sub-pixels
                double reference_variance = 0.0;
                for (int dy = 0; dy < factor; ++dy) {
                    for (int dx = 0; dx < factor; ++dx) {
                        const int rx = x * factor + dx;
                        const int ry = y * factor + dy;
                        const double v = reference.at(rx, ry, ref_c);
                        const double deviation = reference.at(rx, ry, ref_deviation);
                        mean += v;
                        mean_square += v * v;
                        within += deviation * deviation;
                        reference_variance +=
                            deviation * deviation / reference_spp + half_rounding_variance(v);
                        indirect_reference += reference.at(rx, ry, ref_indirect);
                    }
                }
                const double n = factor * factor;
                mean /= n;
                // A render sample lands in a random sub-pixel: its variance is the mean
                // sub-pixel variance plus the variance of the sub-pixel means.
                const double per_sample = within / n + std::max(0.0, mean_square / n - mean * mean);
                const double total_variance =
                    per_sample / options.spp + reference_variance / (n * n);
                const double difference = r.image.at(x, y, test_c) - mean;
                sum_difference += difference;
                sum_variance += total_variance;
                indirect_render += r.image.at(x, y, test_indirect);
                ++values;
                if (difference * difference > 25.0 * total_variance) {
                    ++outliers;
                }
            }
        }
        const double z = sum_difference / std::sqrt(sum_variance);
        EXPECT_LT(std::fabs(z), 5.0) << "channel " << c << ": image-wide z " << z;
        // The indirect layer: image-wide means within 2%.
        indirect_reference /= factor * factor;
        EXPECT_NEAR(indirect_render / indirect_reference, 1.0, 0.02) << "indirect channel " << c;
    }
    EXPECT_LE(outliers, values / 1000) << outliers << " of " << values << " beyond 5 sigma";
    std::printf("%zu of %zu values beyond 5 sigma\n", outliers, values);
}

bool bitwise_equal(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(PathTracer, SameSeedGivesBitwiseIdenticalPixelsWhateverTheChunking) {
    const Scene scene = test::load_cornell_box();
    auto options = test::image_options<PathTracerOptions>(40, 30, 4, 77);
    const Render a = render(scene, options);
    const Render b = render(scene, options);
    EXPECT_TRUE(bitwise_equal(a.image, b.image));
    EXPECT_EQ(a.stats.rays, b.stats.rays);
    Context chunked(test::chunked_context_options(8, 100));
    EXPECT_TRUE(bitwise_equal(a.image, render(scene, options, chunked).image));
    options.seed = 78;
    EXPECT_FALSE(bitwise_equal(a.image, render(scene, options).image));
}

}  // namespace
}  // namespace rc
