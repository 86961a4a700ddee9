// `radcache bench sh` end to end: a tiny run reports its figures and the glossy-box materials'
// adaptive orders in its JSON; bad values of its options are refused by name, with no output.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

TEST(BenchSh, ReportsThroughputAndMaterialOrders) {
    const auto dir = test::scratch_dir("bench_sh");
    const std::string json = (dir / "sh.json").string();
    const test::CommandResult result = test::run_radcache(
        {"bench", "sh", "--records", "8", "--strata", "2", "--resolution", "4", "--json", json});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("SH coefficients projected/s"), std::string::npos);
    const nlohmann::json report = nlohmann::json::parse(read_file(json));
    EXPECT_GT(report["coefficients_projected_per_second"].get<double>(), 0.0);
    EXPECT_GT(report["rotations_per_second"].get<double>(), 0.0);
    EXPECT_GT(report["zxz_rotations_per_second"].get<double>(), 0.0);
    EXPECT_EQ(report["resolution"], 4);
    // Both bases, every material of glossy-box (three diffuse walls, three glossy objects).
    ASSERT_EQ(report["materials"].size(), 12u);
    int diffuse = 0;
    for (const nlohmann::json& m : report["materials"]) {
        diffuse += m["kind"] == "diffuse";
        EXPECT_GE(m["order"].get<int>(), 0);
        EXPECT_LE(m["order"].get<int>(), 10);
    }
    EXPECT_EQ(diffuse, 6);
}

TEST(BenchSh, RefusesBadOptionsWithoutOutput) {
    const auto dir = test::scratch_dir("bench_sh_bad");
    const std::string json = (dir / "sh.json").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--max-error", "0"}, "--max-error"},
        {{"--max-error", "abc"}, "--max-error"},
        {{"--resolution", "1"}, "--resolution"},
        {{"--records", "0"}, "--records"},
        {{"--strata", "0"}, "--strata"},
        {{"--scene", (dir / "missing.json").string()}, "missing.json"},
    };
    for (const auto& [options, expected] : cases) {
        std::vector<std::string> args = {"bench", "sh", "--json", json};
        args.insert(args.end(), options.begin(), options.end());
        const test::CommandResult result = test::run_radcache(args);
        EXPECT_NE(result.exit_code, 0) << options[0];
        EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(json)) << options[0];
    }
}

}  // namespace
}  // namespace rc
