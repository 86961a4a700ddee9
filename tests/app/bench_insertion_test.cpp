// `radcache bench insertion` end to end: a small ic render saves its cache; inserting its records
// again one by one, in batches on one thread and on all threads gives the render's radii bit for
// bit (the command checks each record against the saved file and fails otherwise), level by
// level; a missing or mismatched cache is refused with the file or option named, and no output.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::string cornell_box() {
    return (test::source_dir() / "scenes/cornell-box/scene.json").string();
}

// A two-level cache of the Cornell box at 48 x 48 (a few hundred records per level).
std::string saved_cache(const std::filesystem::path& dir) {
    const std::string cache = (dir / "c.ircache").string();
    const test::CommandResult render = test::run_radcache(
        {"render", cornell_box(), "--method", "ic", "--width", "48", "--height", "48", "--spp", "1",
         "--ic-rays", "64", "--cache-out", cache, "-o", (dir / "c.exr").string()});
    EXPECT_EQ(render.exit_code, 0) << render.output;
    return cache;
}

TEST(BenchInsertion, EveryWayGivesTheSavedRadiiBitForBit) {
    const auto dir = test::scratch_dir("bench_insertion");
    const std::string cache = saved_cache(dir);
    const std::string json = (dir / "insertion.json").string();
    const test::CommandResult result =
        test::run_radcache({"bench", "insertion", "--cache-in", cache, "--batch", "37", "--repeats",
                            "2", "--json", json});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("bit for bit"), std::string::npos) << result.output;
    const nlohmann::json report = nlohmann::json::parse(read_file(json));
    ASSERT_EQ(report["levels"].size(), 2u);
    for (const nlohmann::json& level : report["levels"]) {
        EXPECT_GT(level["records"].get<size_t>(), 37u);
        ASSERT_EQ(level["ways"].size(), 3u);
        for (const nlohmann::json& way : level["ways"]) {
            EXPECT_EQ(way["seconds_each"].size(), 2u);
        }
    }
}

TEST(BenchInsertion, RefusesAMissingOrMismatchedCacheWithoutOutput) {
    const auto dir = test::scratch_dir("bench_insertion_bad");
    const std::string cache = saved_cache(dir);
    const std::string json = (dir / "insertion.json").string();
    // Options refused as usage errors (2), files as input errors (1), as `render` does.
    struct Case {
        std::vector<std::string> options;
        int exit_code;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {{}, 2, "--cache-in"},
        {{"--cache-in", cache, "--batch", "0"}, 2, "--batch"},
        {{"--cache-in", cache, "--repeats", "0"}, 2, "--repeats"},
        {{"--cache-in", (dir / "missing.ircache").string()}, 1, "missing.ircache"},
        {{"--cache-in", cache, "--accuracy", "0.5"}, 1, "c.ircache"},
        {{"--cache-in", cache, "--scene", (dir / "none.json").string()}, 1, "none.json"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = {"bench", "insertion", "--json", json};
        args.insert(args.end(), c.options.begin(), c.options.end());
        const test::CommandResult result = test::run_radcache(args);
        EXPECT_EQ(result.exit_code, c.exit_code) << result.output;
        EXPECT_NE(result.output.find(c.expected), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(json));
    }
}

}  // namespace
}  // namespace rc
