// The caching methods' render passes with several light samples at the camera's hit
// (--light-samples; PipelineSettings::light_samples, IvgRenderOptions::light_samples): the
// same seed gives the same image bit for bit whatever the launch chunking; the direct layer keeps
// its expectation (a per-pixel paired test against one light sample) and loses noise (its squared
// error against the Cornell box's reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "image/image_io.h"
#include "image_options.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/irradiance_vector_grid/ivg_method.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

constexpr int kSize = 64;  // the reference's 512 / 8
constexpr int kSpp = 2;

Image render_ic(Context& context, int light_samples, uint64_t seed) {
    test::DeviceFrame device(test::load_cornell_box(), context);
    CachePipeline cache(device.frame());
    auto options = test::image_options<PipelineSettings>(kSize, kSize, kSpp, seed);
    options.rays = 64;
    options.light_samples = light_samples;
    return cache.render(options);
}

Image render_ivg(Context& context, int light_samples, uint64_t seed) {
    test::DeviceFrame device(test::load_cornell_box(), context);
    IrradianceVectorGrid grid(device.frame());
    IvgOptions grid_options;
    grid_options.cells = {8, 8, 8};
    grid_options.photons = 20000;
    grid_options.seed = 3;
    grid.build(grid_options);
    IvgMethod method(device.frame(), grid);
    auto options = test::image_options<IvgRenderOptions>(kSize, kSize, kSpp, seed);
    options.light_samples = light_samples;
    return method.render(options);
}

using Renderer = Image (*)(Context&, int, uint64_t);
struct Method {
    const char* name;
    Renderer render;
};
const Method kMethods[] = {{"ic", render_ic}, {"ivg", render_ivg}};

bool bitwise_equal(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

int channel(const Image& image, const std::string& name) {
    for (int c = 0; c < image.channels; ++c) {
        if (image.channel_names[c] == name) {
            return c;
        }
    }
    throw Error("no channel " + name);
}

TEST(LightSamples, RenderPassIsBitwiseDeterministicWhateverTheChunking) {
    Context chunked(test::chunked_context_options(8, 1000));
    for (const Method& method : kMethods) {
        const Image a = method.render(test::shared_context(), 4, 7);
        EXPECT_TRUE(bitwise_equal(a, method.render(test::shared_context(), 4, 7))) << method.name;
        EXPECT_TRUE(bitwise_equal(a, method.render(chunked, 4, 7))) << method.name;
    }
}

// With the same seed the camera samples hit the same points, so the per-pixel difference of the
// direct layers with 8 light samples and with 1 has mean zero: within 5 standard errors of its
// own scatter over the pixels. Against the reference (box-filtered to the render's pixels), the
// squared error of the direct layer falls below 0.3 of it (measured: 0.14) where the
// reference is smooth over a pixel (elsewhere the error is mostly the camera jitter's, which
// light samples do not change).
TEST(LightSamples, DirectLayerKeepsItsMeanAndLosesNoise) {
    const Image reference = read_image(test::source_dir() / "scenes/cornell-box/reference.exr");
    const int factor = reference.width / kSize;
    ASSERT_EQ(reference.width, kSize * factor);
    for (const Method& method : kMethods) {
        const Image one = method.render(test::shared_context(), 1, 11);
        const Image many = method.render(test::shared_context(), 8, 11);
        const int channels[3] = {channel(one, "direct.R"), channel(one, "direct.G"),
                                 channel(one, "direct.B")};
        const int reference_channels[3] = {channel(reference, "direct.R"),
                                           channel(reference, "direct.G"),
                                           channel(reference, "direct.B")};
        double sum = 0.0;  // of the per-pixel differences (summed over the channels)
        double sum2 = 0.0;
        double error_one = 0.0;
        double error_many = 0.0;
        const size_t values = static_cast<size_t>(kSize) * kSize;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                double d = 0.0;
                double r[3] = {0.0, 0.0, 0.0};
                double lowest = INFINITY;
                double highest = 0.0;
                for (int j = 0; j < factor; ++j) {
                    for (int i = 0; i < factor; ++i) {
                        double total = 0.0;
                        for (int k = 0; k < 3; ++k) {
                            const double v =
                                reference.at(x * factor + i, y * factor + j, reference_channels[k]);
                            r[k] += v;
                            total += v;
                        }
                        lowest = std::min(lowest, total);
                        highest = std::max(highest, total);
                    }
                }
                for (int k = 0; k < 3; ++k) {
                    r[k] /= factor * factor;
                    d += many.at(x, y, channels[k]) - one.at(x, y, channels[k]);
                }
                sum += d;
                sum2 += d * d;
                if (highest > 1.25 * lowest) {
                    continue;  // an edge, a shadow's border, the emitter: the jitter's error
                }
                for (int k = 0; k < 3; ++k) {
                    const double v1 = one.at(x, y, channels[k]);
                    const double v8 = many.at(x, y, channels[k]);
                    error_one += (v1 - r[k]) * (v1 - r[k]);
                    error_many += (v8 - r[k]) * (v8 - r[k]);
                }
            }
        }
        const double mean = sum / values;
        const double variance = (sum2 / values - mean * mean) * values / (values - 1);
        ASSERT_GT(variance, 0.0) << method.name << ": the light samples change nothing";
        EXPECT_LT(std::fabs(mean), 5.0 * std::sqrt(variance / values)) << method.name;
        std::printf("%s: direct squared error with 8 light samples / with 1: %.3f\n", method.name,
                    error_many / error_one);
        EXPECT_LT(error_many, 0.3 * error_one) << method.name;
    }
}

}  // namespace
}  // namespace rc
