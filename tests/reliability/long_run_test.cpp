// Long runs: a 24-frame animation with a caching method keeps its memory bounded. The
// --stats file reports each frame's host and device memory; device memory held at the end of a
// frame must not grow over the frames, nor the peak within a frame, nor the host's resident
// memory beyond allocator noise. (Radiance caching rebuilds its BRDF tables each frame, about
// three seconds on PoCL: its 24-frame run is documented in docs/reliability.md instead.) The
// device-memory cap is device_memory_need_test's.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

struct AnimatedRun {
    std::string name;
    std::string method;
    std::vector<std::string> options;
};

void PrintTo(const AnimatedRun& run, std::ostream* out) { *out << run.name; }

class LongRun : public testing::TestWithParam<AnimatedRun> {};

uint64_t memory_of(const nlohmann::json& frame, const char* key) {
    return frame.at("memory").at(key).get<uint64_t>();
}

TEST_P(LongRun, TwentyFourFramesKeepMemoryBounded) {
    const AnimatedRun& run = GetParam();
    const auto dir = test::scratch_dir("long_run_" + run.name);
    std::vector<std::string> args = {
        "render",
        (test::source_dir() / "scenes/moving-sphere/scene.json").string(),
        "--frames",
        "0:23",
        "-o",
        (dir / "f####.png").string(),
        "--width",
        "16",
        "--height",
        "16",
        "--spp",
        "1",
        "--quiet",
        "--stats",
        (dir / "stats.json").string(),
        "--method",
        run.method};
    args.insert(args.end(), run.options.begin(), run.options.end());
    const test::CommandResult result = test::run_radcache(args);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    const nlohmann::json& frames = stats.at("frames");
    ASSERT_EQ(frames.size(), 24u);

    // Device memory: the scene's buffers and whatever the method keeps, at the end of each frame
    // and at its peak; the sphere's records change from frame to frame, so within a band around
    // the first frames' figures, and never a trend (a leak of one buffer per frame would add a
    // film's worth each frame).
    for (const char* key : {"device_bytes", "device_peak_bytes"}) {
        uint64_t early = 0;
        for (size_t f = 0; f < 4; ++f) {
            early = std::max(early, memory_of(frames[f], key));
        }
        ASSERT_GT(early, 0u) << key;
        for (size_t f = 4; f < frames.size(); ++f) {
            EXPECT_LE(memory_of(frames[f], key), early + early / 8)
                << key << " at frame " << f << " against " << early << " in frames 0-3";
        }
    }
    EXPECT_GE(stats.at("memory").at("device_peak_bytes").get<uint64_t>(),
              memory_of(frames[23], "device_peak_bytes"));
#if !defined(__SANITIZE_ADDRESS__)
    // Host memory: resident size in the second half of the run within 8 MiB of the middle (ASan's
    // quarantine grows it by design, so not under the sanitizer build).
    const uint64_t middle = memory_of(frames[11], "host_resident_bytes");
    for (size_t f = 12; f < frames.size(); ++f) {
        EXPECT_LE(memory_of(frames[f], "host_resident_bytes"), middle + (8u << 20))
            << "host memory at frame " << f;
    }
#endif
}

INSTANTIATE_TEST_SUITE_P(
    CachingMethods, LongRun,
    testing::Values(
        AnimatedRun{"ic", "ic", {"--ic-rays", "16", "--ic-bounces", "2"}},
        // Temporal caching keeps its records across the frames: bounded by their lifespans.
        AnimatedRun{"ic_temporal", "ic", {"--temporal", "--ic-rays", "16"}},
        AnimatedRun{
            "sdrc", "sdrc", {"--ic-rays", "16", "--ic-bounces", "1", "--sdrc-samples", "16"}},
        AnimatedRun{"ivg", "ivg", {"--photons", "4000", "--grid", "4x4x4"}},
        AnimatedRun{"ivg_gather",
                    "ivg-gather",
                    {"--photons", "4000", "--grid", "4x4x4", "--gather-rays", "4"}}),
    [](const testing::TestParamInfo<AnimatedRun>& info) { return info.param.name; });

}  // namespace
}  // namespace rc
