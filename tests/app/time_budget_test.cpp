// `render --time T` bounds the render by time, not by --spp: with an absurd --spp the process still
// ends (CTest's TIMEOUT on this test turns an ignored --time into a failure instead of a hang),
// renders at least one pass and far fewer than --spp, and reports at least T seconds of rendering.
// Every other method renders by time too: its cache, then passes of camera samples over it, the
// split reported in the stats; temporal caching refuses it. Only the command line is used.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "image/image.h"
#include "image/image_io.h"
#include "methods/registry.h"
#include "test_support.h"
#include "timed_render.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::string cornell_box() {
    return (test::source_dir() / "scenes/cornell-box/scene.json").string();
}

// The largest --spp the command line accepts: at 16 x 16 pixels, rendering all of it would take
// hours, far beyond the test's TIMEOUT.
constexpr int kAbsurdSpp = 1 << 24;

TEST(TimeBudget, StopsByTimeLongBeforeAnAbsurdSampleCount) {
    const auto dir = test::scratch_dir("time_budget");
    const double budget = 0.5;
    const test::CommandResult result = test::run_radcache(
        {"render", cornell_box(), "-o", (dir / "out.exr").string(), "--method", "pt", "--time",
         "0.5", "--spp", std::to_string(kAbsurdSpp), "--width", "16", "--height", "16", "--quiet",
         "--stats", (dir / "stats.json").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    const int spp = stats["spp"].get<int>();
    EXPECT_GE(spp, 1);
    // (A pass of 256 paths a microsecond is beyond any device: the budget, not --spp, ended it.)
    EXPECT_LT(spp, kAbsurdSpp / 16) << "the render went on to a sample count, not a time";
    ASSERT_EQ(stats["frames"].size(), 1u);
    EXPECT_EQ(stats["frames"][0]["spp"].get<int>(), spp);
    // The passes ran until the budget was spent: the frame's own clock and the render phase.
    EXPECT_GE(stats["frames"][0]["seconds"].get<double>(), budget);
    EXPECT_GE(stats["seconds"]["render"].get<double>(), budget);
    // The image is the passes' mean: finite and lit.
    test::expect_finite_lit_beauty(dir / "out.exr");
}

TEST(TimeBudget, EveryMethodRendersByTime) {
    for (const MethodEntry& entry : method_registry()) {
        if (entry.name == "pt" || entry.name == "auto") {
            continue;  // above; auto plans its samples from --time (auto_test.cpp)
        }
        // A budget the first pass (the cache and one sample per pixel) may exceed: one pass at
        // least, the samples and the split reported.
        SCOPED_TRACE(entry.name);
        test::render_cornell_by_time("time_" + entry.name,
                                     {"--method", entry.name, "--time", "0.5", "--spp", "16",
                                      "--width", "12", "--height", "12"},
                                     16);
    }
}

TEST(TimeBudget, ACheapCacheLeavesTimeForMoreSamplesWithinTheBudget) {
    // 64 rays a record on 12 x 12 pixels: the cache takes a fraction of a second here, so a
    // budget of 4 s holds many more passes; the frame ends near the budget (a generous bound:
    // the precise figures are the benchmark's).
    const double budget = 4.0;
    const nlohmann::json frame =
        test::render_cornell_by_time("time_ic_passes",
                                     {"--method", "ic", "--time", "4", "--ic-rays", "64", "--spp",
                                      "64", "--width", "12", "--height", "12"},
                                     64);
    ASSERT_TRUE(frame.contains("time"));
    EXPECT_GT(frame["time"]["passes"].get<int>(), 2);
    EXPECT_GT(frame["spp"].get<int>(), 4);
    const double seconds = frame["time"]["first_pass_seconds"].get<double>() +
                           frame["time"]["later_passes_seconds"].get<double>();
    EXPECT_GT(seconds, 0.5 * budget);
    EXPECT_LT(seconds, 3.0 * budget);
}

TEST(TimeBudget, TemporalCachingRefusesIt) {
    const auto dir = test::scratch_dir("time_temporal");
    for (const std::string method : {"ic", "rc"}) {
        const test::CommandResult result = test::run_radcache(
            {"render", cornell_box(), "-o", (dir / "out.png").string(), "--method", method,
             "--temporal", "--time", "0.5", "--width", "8", "--height", "8", "--quiet"});
        EXPECT_EQ(result.exit_code, 2) << method << ": " << result.output;
        EXPECT_NE(result.output.find("--time: temporal caching"), std::string::npos)
            << method << ": " << result.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << method;
    }
}

}  // namespace
}  // namespace rc
