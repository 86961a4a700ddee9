// `--method decomposition` rendered by time (--time): after render() of one camera sample per
// pixel, IrradianceDecomposition::render_samples shades camera samples first .. first + spp - 1
// over the same near and far fields (the clusters are those of each pixel's first sample either
// way), so the passes, weighted by their samples, are one render of as many samples to float
// rounding, and a later pass traces no cluster or radiosity ray. Through the command line: a
// render by time ends with the frame's samples and passes in its stats, and
// --decomp-indirect-spp with --time is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "image_options.h"
#include "methods/decomposition/decomposition.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "test_support.h"
#include "timed_render.h"

namespace rc {
namespace {

std::string cornell_box() {
    return (test::source_dir() / "scenes/cornell-box/scene.json").string();
}

// The Cornell box's decomposition at 16 x 16 over a small grid, `spp` samples per pixel.
DecompositionOptions small_options(const RadianceSource* source, int spp) {
    auto options = test::image_options<DecompositionOptions>(16, 16, spp, 5);
    options.alpha = 30.0f;
    options.min_cluster_size = 30.0f;
    options.cluster_rays = 128;
    options.source = source;
    return options;
}

// render() at 1 spp, then render_samples {1, 1} and {2, 2}, weighted by their samples: render()
// at 4 spp in every layer; each pass differs from it; the same fields (far-field samples, near
// triangles), and the later passes trace no cluster or radiosity ray.
TEST(DecompositionByTime, PassesOverOneDecompositionDrawTheSamplesOfOneLongerRender) {
    test::DeviceFrame cornell(test::load_cornell_box());
    const FrameScene frame = cornell.frame();  // (the grid keeps a reference to it)
    IrradianceVectorGrid grid(frame);
    IvgOptions grid_options;
    grid_options.photons = 20000;
    grid_options.seed = 3;
    grid.build(grid_options);

    IrradianceDecomposition whole(frame);
    DecompositionStats whole_stats;
    const Image four = whole.render(small_options(&grid, 4), &whole_stats);

    IrradianceDecomposition split(frame);
    DecompositionStats first_stats, second_stats, third_stats;
    const Image passes[3] = {split.render(small_options(&grid, 1), &first_stats),
                             split.render_samples(1, 1, &second_stats),
                             split.render_samples(2, 2, &third_stats)};
    test::expect_passes_make_the_longer_render(four, {passes[0], passes[1], passes[2]}, {1, 1, 2},
                                               1e-5);
    EXPECT_EQ(first_stats.sh_samples, whole_stats.sh_samples);
    EXPECT_EQ(first_stats.near_triangles, whole_stats.near_triangles);
    EXPECT_EQ(first_stats.cluster_rays, whole_stats.cluster_rays);
    EXPECT_GT(first_stats.cluster_rays, 0u);
    for (const DecompositionStats* later : {&second_stats, &third_stats}) {
        EXPECT_EQ(later->cluster_rays, 0u);
        EXPECT_EQ(later->radiosity_rays, 0u);
        EXPECT_EQ(later->sh_samples, whole_stats.sh_samples);
        EXPECT_GT(later->shading_rays, 0u);
    }
    EXPECT_EQ(first_stats.served_samples + second_stats.served_samples + third_stats.served_samples,
              whole_stats.served_samples);
}

// `render --method decomposition --time 2`: exit 0, a finite, lit image; the stats' time split
// has at least one pass and the frame's samples; the later passes' samples are consecutive, at
// most --spp each, and trace no cluster ray (their stats hold none).
TEST(DecompositionByTime, RenderByTimeThroughTheCommandLine) {
    // (--alpha 5 %: a near field quick enough on a CPU device to leave time for later passes.)
    const nlohmann::json frame = test::render_cornell_by_time(
        "decomposition_time",
        {"--method", "decomposition", "--time", "2", "--spp", "4", "--photons", "2000",
         "--decomp-rays", "64", "--alpha", "5%", "--width", "16", "--height", "16"},
        4);
    EXPECT_GT(frame.value("cluster_rays_traced", uint64_t{0}), 0u);
    for (const nlohmann::json& pass : frame.value("passes", nlohmann::json::array())) {
        EXPECT_FALSE(pass.contains("cluster_rays_traced"));
        EXPECT_FALSE(pass.contains("grid"));
    }
}

// --decomp-indirect-spp has no place in a render by time: exit status 2, one line naming both
// options, no output file.
TEST(DecompositionByTime, IndirectSamplesWithTimeAreRefused) {
    const auto dir = test::scratch_dir("decomposition_time_refused");
    const test::CommandResult result =
        test::run_radcache({"render", cornell_box(), "-o", (dir / "out.exr").string(), "--method",
                            "decomposition", "--time", "1", "--spp", "2", "--decomp-indirect-spp",
                            "4", "--width", "8", "--height", "8", "--quiet"});
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--decomp-indirect-spp"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("--time"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace rc
