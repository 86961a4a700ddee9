// Programs started in the background at start-up (Context::prebuild, Method::programs):
// a small render of every method, and of the options that change its programs, builds exactly
// the programs it started in the background (render --stats: program_builds against
// prebuilt_programs), so a cold render builds all of them at once and none in vain.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "methods/registry.h"
#include "test_support.h"

namespace rc {
namespace {

struct Case {
    std::string name;
    std::string scene;  // under scenes/
    std::vector<std::string> options;
};

void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

std::vector<Case> cases() {
    std::vector<Case> all;
    for (const MethodEntry& method : method_registry()) {
        // A method with a glossy layer renders a scene with glossy materials, whose programs it
        // builds only there.
        const bool glossy = std::find(method.aovs.begin(), method.aovs.end(), "glossy-indirect") !=
                            method.aovs.end();
        all.push_back(
            {method.name, glossy ? "glossy-box" : "cornell-box", {"--method", method.name}});
    }
    all.push_back({"ic_one_level", "cornell-box", {"--method", "ic", "--ic-bounces", "1"}});
    all.push_back({"ic_grid", "cornell-box", {"--method", "ic", "--ic-ivg"}});
    all.push_back({"ic_temporal",
                   "moving-sphere",
                   {"--method", "ic", "--temporal", "--frames", "0:1", "-o", "#"}});
    all.push_back({"rc_temporal",
                   "glossy-box",
                   {"--method", "rc", "--temporal", "--frames", "0:1", "-o", "#"}});
    all.push_back({"ic_glossy_rc", "glossy-box", {"--method", "ic", "--glossy", "rc"}});
    all.push_back(
        {"ic_glossy_mix", "glossy-box", {"--method", "ic", "--glossy", "satin=rc,brushed=sdrc"}});
    all.push_back({"decomposition_path",
                   "cornell-box",
                   {"--method", "decomposition", "--decomp-source", "path"}});
    return all;
}

using ProgramSet = std::set<std::pair<std::string, std::string>>;

ProgramSet programs(const nlohmann::json& list) {
    ProgramSet set;
    for (const nlohmann::json& p : list) {
        set.insert({p.at("program").get<std::string>(), p.at("options").get<std::string>()});
    }
    return set;
}

class EveryMethodsPrograms : public ::testing::TestWithParam<Case> {};

TEST_P(EveryMethodsPrograms, AreExactlyThoseItPrebuilds) {
    const Case& c = GetParam();
    const auto dir = test::scratch_dir("prebuild_" + c.name);
    const std::string stats = (dir / "stats.json").string();
    std::vector<std::string> args = {
        "render",   (test::source_dir() / "scenes" / c.scene / "scene.json").string(),
        "--width",  "12",
        "--height", "12",
        "--spp",    "1",
        "--stats",  stats,
        "-q"};
    // Small settings for the options the method declares.
    const std::vector<std::string> quick =
        test::quick_method_options(find_method(c.options.at(1)), c.options);
    args.insert(args.end(), quick.begin(), quick.end());
    std::string output = (dir / "out.exr").string();
    for (size_t i = 0; i < c.options.size(); ++i) {
        if (c.options[i] == "-o") {
            output = (dir / "f####.exr").string();
            ++i;
        } else {
            args.push_back(c.options[i]);
        }
    }
    args.insert(args.end(), {"-o", output});
    const test::CommandResult result = test::run_radcache(args);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::ifstream file(stats);
    const nlohmann::json json = nlohmann::json::parse(file);
    const ProgramSet built = programs(json.at("program_builds"));
    const ProgramSet prebuilt = programs(json.at("prebuilt_programs"));
    EXPECT_FALSE(prebuilt.empty());
    if (c.name == "auto") {
        // auto prebuilds every method its plan may choose, and builds those of its pilot and its
        // plan: none outside the list.
        EXPECT_TRUE(std::includes(prebuilt.begin(), prebuilt.end(), built.begin(), built.end()));
        EXPECT_FALSE(built.empty());
        return;
    }
    EXPECT_EQ(built, prebuilt);
}

// Whether every program of a render's --stats came from the binary cache.
bool all_from_cache(const std::string& stats) {
    std::ifstream file(stats);
    const nlohmann::json json = nlohmann::json::parse(file);
    bool all = !json.at("program_builds").empty();
    for (const nlohmann::json& build : json.at("program_builds")) {
        all = all && build.at("from_cache").get<bool>();
    }
    return all;
}

TEST(Warmup, FillsTheCacheSoTheRenderCompilesNothing) {
    const auto dir = test::scratch_dir("warmup");
    const std::vector<std::string> cold_env = {"RADCACHE_CACHE_DIR=" + (dir / "cold").string()};
    const std::vector<std::string> warm_env = {"RADCACHE_CACHE_DIR=" + (dir / "warm").string()};
    const auto render = [&](const std::vector<std::string>& env, const std::string& name) {
        const std::string stats = (dir / (name + ".json")).string();
        const test::CommandResult result = test::run_radcache(
            {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "-o",
             (dir / (name + ".exr")).string(), "--method", "ic", "--ic-bounces", "1", "--ic-rays",
             "32", "--width", "8", "--height", "8", "--spp", "1", "--stats", stats, "-q"},
            env);
        EXPECT_EQ(result.exit_code, 0) << result.output;
        return stats;
    };
    // Without a warm-up, an empty cache compiles.
    EXPECT_FALSE(all_from_cache(render(cold_env, "cold")));
    const test::CommandResult warmup =
        test::run_radcache({"warmup", "--method", "ic", "--ic-bounces", "1"}, warm_env);
    ASSERT_EQ(warmup.exit_code, 0) << warmup.output;
    // ic's two and the loop probe's (host/device/device_features.h), which every render runs.
    EXPECT_NE(warmup.output.find("3 programs"), std::string::npos) << warmup.output;
    EXPECT_TRUE(all_from_cache(render(warm_env, "warm")));
}

TEST(Warmup, RefusesUnknownMethodsAndForeignOptions) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"warmup", "--method", "nosuch"},
          std::vector<std::string>{"warmup", "--method", "pt", "--ic-rays", "8"},
          std::vector<std::string>{"warmup", "scene.json"}}) {
        const test::CommandResult result = test::run_radcache(args);
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryMethodsPrograms, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             std::string name = info.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace rc
