// The fuzz targets (tests/fuzz/) over their seeds and over every input the fuzzers have saved
// (tests/fuzz/regressions/<target>/, each a crash, hang or leak that was found and fixed): each
// must return normally. A crash fails this test program; an exception other than rc::Error fails
// the test case. The fuzz build runs the same targets under libFuzzer (tools/fuzz.sh).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fuzz_targets.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::vector<std::filesystem::path> inputs_of(const std::string& target, const std::string& kind) {
    std::vector<std::filesystem::path> files;
    const auto dir = test::source_dir() / "tests/fuzz" / kind / target;
    if (std::filesystem::is_directory(dir)) {
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

int run_target(const fuzz::Target& target, const std::string& bytes) {
    return target.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

TEST(FuzzRegression, EveryTargetHasSeedsAndReturnsOnThemAndOnEveryFoundInput) {
    for (const fuzz::Target& target : fuzz::kTargets) {
        const auto seeds = inputs_of(target.name, "seeds");
        EXPECT_FALSE(seeds.empty()) << target.name << " has no seeds";
        for (const std::string kind : {"seeds", "regressions"}) {
            for (const auto& input : inputs_of(target.name, kind)) {
                SCOPED_TRACE(input.string());
                EXPECT_EQ(run_target(target, read_file(input)), 0);
            }
        }
    }
}

// The scene target over every shipped scene with its small meshes, as tools/fuzz.sh seeds it.
TEST(FuzzRegression, TheSceneTargetLoadsTheShippedScenes) {
    for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "scenes")) {
        const auto scene = entry.path() / "scene.json";
        if (!std::filesystem::is_regular_file(scene)) {
            continue;
        }
        std::string input = read_file(scene);
        for (const auto& file : std::filesystem::recursive_directory_iterator(entry.path())) {
            if (file.path().extension() == ".obj" && file.file_size() < 65536) {
                input += "\n#@file " +
                         std::filesystem::relative(file.path(), entry.path()).string() + "\n" +
                         read_file(file.path());
            }
        }
        SCOPED_TRACE(scene.string());
        EXPECT_EQ(fuzz::scene(reinterpret_cast<const uint8_t*>(input.data()), input.size()), 0);
    }
}

TEST(FuzzRegression, InputsSplitIntoFiles) {
    const std::string input = "{\"a\": 1}\n#@file m/x.obj\nv 0 0 0\n#@file y.mtl\nKd 1\n";
    const auto files = fuzz::split_files(reinterpret_cast<const uint8_t*>(input.data()),
                                         input.size(), "scene.json");
    ASSERT_EQ(files.size(), 3u);
    EXPECT_EQ(files[0], std::make_pair(std::string("scene.json"), std::string("{\"a\": 1}\n")));
    EXPECT_EQ(files[1], std::make_pair(std::string("m/x.obj"), std::string("v 0 0 0\n")));
    EXPECT_EQ(files[2], std::make_pair(std::string("y.mtl"), std::string("Kd 1\n")));
}

}  // namespace
}  // namespace rc
