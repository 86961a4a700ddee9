// `ivg` and `ivg-gather` rendered by time (--time): a pass shades camera samples
// first_sample .. first_sample + spp - 1 over a grid built once (IvgRenderOptions::first_sample),
// so passes over one grid, weighted by their samples, are one render of as many samples to float
// rounding; through the command line, a render by time builds the grid in its first pass only and
// reports the frame's samples and passes in its stats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "image_options.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/irradiance_vector_grid/ivg_method.h"
#include "test_support.h"
#include "timed_render.h"

namespace rc {
namespace {

// For the grid read at the camera's hit and for final gathering: passes {0, 1}, {1, 1} and
// {2, 2} over one grid, weighted by their samples, give the 4-sample render over it in every
// layer; each pass alone differs from it. First sample 0 is bitwise the render as before.
TEST(IvgByTime, PassesOverOneGridDrawTheSamplesOfOneLongerRender) {
    test::DeviceFrame cornell(test::load_cornell_box());
    const FrameScene frame = cornell.frame();  // (the grid and the method keep references)
    IrradianceVectorGrid grid(frame);
    IvgOptions grid_options;
    grid_options.cells = {8, 8, 8};
    grid_options.photons = 20000;
    grid_options.seed = 3;
    grid.build(grid_options);
    IvgMethod method(frame, grid);
    for (const int gather_rays : {0, 4}) {
        SCOPED_TRACE(gather_rays);
        const auto render = [&](int first, int spp) {
            auto options = test::image_options<IvgRenderOptions>(24, 24, spp, 9);
            options.gather_rays = gather_rays;
            options.first_sample = first;
            return method.render(options);
        };
        const Image four = render(0, 4);
        const Image passes[3] = {render(0, 1), render(1, 1), render(2, 2)};
        test::expect_passes_make_the_longer_render(four, {passes[0], passes[1], passes[2]},
                                                   {1, 1, 2}, 1e-5);
        auto plain = test::image_options<IvgRenderOptions>(24, 24, 2, 9);
        plain.gather_rays = gather_rays;
        EXPECT_EQ(method.render(plain).pixels, render(0, 2).pixels);
    }
}

// `render --method M --time 2` with a small grid: exit 0, a finite, lit image; the stats' time
// split has at least one pass and the frame's samples; the grid's figures are the first pass's
// (frames[0]["grid"]) and no later pass built one; the later passes' samples are consecutive and
// at most --spp each.
TEST(IvgByTime, RenderByTimeThroughTheCommandLineBuildsTheGridOnce) {
    for (const std::string method : {"ivg", "ivg-gather"}) {
        SCOPED_TRACE(method);
        std::vector<std::string> options = {"--method", method,   "--time",   "2",         "--spp",
                                            "4",        "--grid", "4x4x4",    "--photons", "2000",
                                            "--width",  "16",     "--height", "16"};
        if (method == "ivg-gather") {
            options.insert(options.end(), {"--gather-rays", "2"});
        }
        const nlohmann::json frame = test::render_cornell_by_time("ivg_time_" + method, options, 4);
        EXPECT_TRUE(frame.contains("grid"));
        for (const nlohmann::json& pass : frame.value("passes", nlohmann::json::array())) {
            EXPECT_FALSE(pass.contains("grid")) << "a later pass built a grid";
        }
    }
}

}  // namespace
}  // namespace rc
