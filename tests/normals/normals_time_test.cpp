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
#include "timed_render.h"

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

// Passes {0, 1}, {1, 1} and {2, 2}, weighted by their samples, give the 4-sample render; each
// pass alone differs from it (the passes draw different samples, not the same one again).
TEST(NormalsByTime, PassesDrawTheSamplesOfOneLongerRender) {
    test::DeviceFrame cornell(test::load_cornell_box());
    const FrameScene frame = cornell.frame();  // (NormalsMethod keeps a reference to it)
    NormalsMethod method(frame);
    const Image four = render_samples(method, 0, 4);
    const Image passes[3] = {render_samples(method, 0, 1), render_samples(method, 1, 1),
                             render_samples(method, 2, 2)};
    const Image mean = test::mean_of_passes({passes[0], passes[1], passes[2]}, {1, 1, 2});
    EXPECT_LT(test::relative_difference(mean, four), 1e-6);
    for (const Image& pass : passes) {
        EXPECT_GT(test::relative_difference(pass, four), 1e-3);
    }
    EXPECT_GT(test::relative_difference(passes[0], passes[1]), 1e-3);
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
    test::render_cornell_by_time(
        "normals_time",
        {"--method", "normals", "--time", "0.5", "--spp", "4", "--width", "16", "--height", "16"},
        4);
}

}  // namespace
}  // namespace rc
