// `--method normals` rendered by time (--time): its passes draw the camera samples one render of
// as many samples would (NormalsOptions::first_sample; the preview is a deterministic function
// of the sample positions, so the passes' weighted mean is that render to float rounding), and a
// render by time through the command line ends with the frame's samples and passes in its stats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "methods/normals/normals.h"
#include "test_support.h"

namespace rc {
namespace {

// Camera samples first .. first + spp - 1 of every pixel of the Cornell box at 32 x 32, jittered.
Image render_samples(NormalsMethod& method, unsigned first, unsigned spp) {
    NormalsOptions options;
    options.width = 32;
    options.height = 32;
    options.samples_per_pixel = spp;
    options.first_sample = first;
    options.jitter = NormalsOptions::Jitter::kAlways;
    options.seed = 11;
    return method.render(options);
}

// The largest pixel difference of two images over the largest magnitude in either.
double relative_difference(const Image& a, const Image& b) {
    EXPECT_EQ(a.pixels.size(), b.pixels.size());
    double largest = 0.0, difference = 0.0;
    for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
        largest =
            std::max({largest, std::fabs(double(a.pixels[i])), std::fabs(double(b.pixels[i]))});
        difference = std::max(difference, std::fabs(double(a.pixels[i]) - double(b.pixels[i])));
    }
    return largest > 0.0 ? difference / largest : difference;
}

// Passes {0, 1}, {1, 1} and {2, 2}, weighted by their samples, give the 4-sample render; each
// pass alone differs from it (the passes draw different samples, not the same one again).
TEST(NormalsByTime, PassesDrawTheSamplesOfOneLongerRender) {
    test::DeviceFrame cornell(test::load_cornell_box());
    const FrameScene frame = cornell.frame();  // (NormalsMethod keeps a reference to it)
    NormalsMethod method(frame);
    const Image four = render_samples(method, 0, 4);
    const Image passes[3] = {render_samples(method, 0, 1), render_samples(method, 1, 1),
                             render_samples(method, 2, 2)};
    const double weights[3] = {1.0, 1.0, 2.0};
    Image mean = four;
    for (size_t i = 0; i < mean.pixels.size(); ++i) {
        double sum = 0.0;
        for (int p = 0; p < 3; ++p) {
            sum += weights[p] * passes[p].pixels[i];
        }
        mean.pixels[i] = static_cast<float>(sum / 4.0);
    }
    EXPECT_LT(relative_difference(mean, four), 1e-6);
    for (const Image& pass : passes) {
        EXPECT_GT(relative_difference(pass, four), 1e-3);
    }
    EXPECT_GT(relative_difference(passes[0], passes[1]), 1e-3);
}

// First sample 0: bitwise the render without a first sample (the default), jittered or not.
TEST(NormalsByTime, FirstSampleZeroIsTheRenderAsBefore) {
    test::DeviceFrame cornell(test::load_cornell_box());
    const FrameScene frame = cornell.frame();  // (NormalsMethod keeps a reference to it)
    NormalsMethod method(frame);
    NormalsOptions options;
    options.width = 16;
    options.height = 16;
    options.samples_per_pixel = 3;
    options.seed = 11;
    const Image plain = method.render(options);
    options.first_sample = 0;
    options.jitter = NormalsOptions::Jitter::kAlways;
    const Image jittered = method.render(options);
    EXPECT_EQ(plain.pixels, jittered.pixels);
}

// `render --method normals --time 0.5`: exit 0, a finite image, and the stats' time split: at
// least one pass, its samples the frame's and the render's, the passes' samples consecutive.
TEST(NormalsByTime, RenderByTimeThroughTheCommandLine) {
    const auto dir = test::scratch_dir("normals_time");
    const test::CommandResult result = test::run_radcache(
        {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "-o",
         (dir / "out.exr").string(), "--method", "normals", "--time", "0.5", "--spp", "4",
         "--width", "16", "--height", "16", "--quiet", "--stats", (dir / "stats.json").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir / "stats.json"));
    const nlohmann::json& frame = stats["frames"][0];
    const nlohmann::json& time = frame["time"];
    EXPECT_GE(time["passes"].get<int>(), 1);
    EXPECT_GE(time["spp"].get<int>(), 1);
    EXPECT_EQ(time["spp"], frame["spp"]);
    EXPECT_EQ(stats["spp"], frame["spp"]);
    int next = 1;
    for (const nlohmann::json& pass : frame["passes"]) {
        EXPECT_EQ(pass["first_sample"].get<int>(), next);
        EXPECT_LE(pass["spp"].get<int>(), 4);
        next += pass["spp"].get<int>();
    }
    EXPECT_EQ(next, frame["spp"].get<int>());
    EXPECT_EQ(time["passes"].get<size_t>(), frame["passes"].size() + 1);
    const Image image = read_image(dir / "out.exr");
    double sum = 0.0;
    for (float v : image.pixels) {
        ASSERT_TRUE(std::isfinite(v));
        sum += v;
    }
    EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace rc
