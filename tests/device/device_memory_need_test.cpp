// The device memory a render needs, checked up front (device/memory_need.h): a render
// that cannot fit in --device-memory is refused before its first buffer with the whole figure,
// and the figure is tested against the peak the run measures (Context::device_memory, reported
// by --stats) for every registered method: equal to it where the figure leaves nothing out (the
// buffers the options fix), at most it where the method names what it leaves out (a caching
// method's records and record batches, which grow with what it finds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <regex>

#include "methods/registry.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

struct MethodRun {
    std::string name;
    std::vector<std::string> options;  // --method and its options
};

void PrintTo(const MethodRun& run, std::ostream* out) { *out << run.name; }

std::vector<std::string> render_args(const std::filesystem::path& dir, const std::string& scene,
                                     int size, const std::vector<std::string>& options) {
    std::vector<std::string> args = {
        "render",   (test::source_dir() / "scenes" / scene / "scene.json").string(),
        "-o",       (dir / "out.png").string(),
        "--width",  std::to_string(size),
        "--height", std::to_string(size),
        "--spp",    "1",
        "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    return args;
}

class DeviceMemoryNeed : public testing::TestWithParam<MethodRun> {};

// The figure the render was checked against, and the peak it then measured.
TEST_P(DeviceMemoryNeed, IsTheMeasuredPeakOrAtMostIt) {
    const MethodRun& run = GetParam();
    const auto dir = test::scratch_dir("memory_need_" + run.name);
    std::vector<std::string> args = render_args(dir, "cornell-box", 16, run.options);
    args.insert(args.end(), {"--stats", (dir / "stats.json").string()});
    const test::CommandResult result = test::run_radcache(args);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    const nlohmann::json& memory = stats.at("frames").at(0).at("memory");
    const auto need = memory.at("device_need_bytes").get<uint64_t>();
    const auto peak = memory.at("device_peak_bytes").get<uint64_t>();
    const std::string excludes = memory.at("device_need_excludes").get<std::string>();
    uint64_t parts = 0;
    for (const auto& [name, bytes] : memory.at("device_need_parts").items()) {
        parts += bytes.get<uint64_t>();
    }
    EXPECT_EQ(parts, need);
    EXPECT_GT(memory.at("device_need_parts").at("scene").get<uint64_t>(), 0u);
    EXPECT_GT(memory.at("device_need_parts").at("BVH").get<uint64_t>(), 0u);
    // A method whose buffers its options fix names nothing the figure leaves out.
    if (excludes.empty()) {
        EXPECT_EQ(need, peak) << "need " << need << ", peak " << peak;
    } else {
        EXPECT_LE(need, peak) << "need " << need << ", peak " << peak << ", excluding " << excludes;
    }
}

// Every registered method at small settings, and the options that change what it holds.
std::vector<MethodRun> method_runs() {
    std::vector<MethodRun> runs;
    const auto add = [&](const std::string& name, const std::string& method,
                         std::vector<std::string> options) {
        const std::vector<std::string> quick =
            test::quick_method_options(find_method(method), options);
        options.insert(options.end(), quick.begin(), quick.end());
        options.insert(options.begin(), {"--method", method});
        runs.push_back({name, options});
    };
    for (const MethodEntry& method : method_registry()) {
        std::string name = method.name;
        std::replace(name.begin(), name.end(), '-', '_');
        add(name, method.name, {});
    }
    add("ivg_compressed", "ivg", {"--grid", "6x5x4", "--ivg-compressed"});
    add("ic_grid", "ic", {"--ic-ivg", "--ic-bounces", "1"});
    return runs;
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, DeviceMemoryNeed, testing::ValuesIn(method_runs()),
                         [](const testing::TestParamInfo<MethodRun>& info) {
                             return info.param.name;
                         });

// The MiB figure of "the render needs [at least ]X MiB of device memory".
double needed_mebibytes(const std::string& output) {
    static const std::regex figure(
        R"(the render needs (at least )?([0-9.]+) MiB of device memory)");
    std::smatch match;
    if (!std::regex_search(output, match, figure)) {
        return -1.0;
    }
    return std::strtod(match[2].str().c_str(), nullptr);
}

// Refused before its first buffer with the whole figure (the peak a run with room measures), one
// line, exit status 1, no image and no stats file; with the figure's MiB rounded up it renders.
TEST(DeviceMemoryLimit, ARenderThatCannotFitIsRefusedUpFrontWithItsWholeNeed) {
    const auto dir = test::scratch_dir("memory_need_limit");
    const std::vector<std::string> method = {"--method", "pt"};
    std::vector<std::string> measured = render_args(dir, "cornell-box", 256, method);
    measured.insert(measured.end(), {"--stats", (dir / "peak.json").string()});
    const test::CommandResult roomy = test::run_radcache(measured);
    ASSERT_EQ(roomy.exit_code, 0) << roomy.output;
    const double peak = static_cast<double>(nlohmann::json::parse(read_file(dir / "peak.json"))
                                                .at("memory")
                                                .at("device_peak_bytes")
                                                .get<uint64_t>()) /
                        (1024.0 * 1024.0);
    std::filesystem::remove(dir / "out.png");
    ASSERT_GT(peak, 2.0);  // the film: 256 x 256 x 6 float4

    std::vector<std::string> tight = render_args(dir, "cornell-box", 256, method);
    tight.insert(tight.end(), {"--stats", (dir / "stats.json").string(), "--device-memory", "2"});
    const test::CommandResult refused = test::run_radcache(tight);
    EXPECT_EQ(refused.exit_code, 1) << refused.output;
    EXPECT_NEAR(needed_mebibytes(refused.output), peak, 0.006) << refused.output;
    EXPECT_NE(refused.output.find("(scene "), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("film 6.00 MiB"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("more than the 2.00 MiB of --device-memory"), std::string::npos)
        << refused.output;
    EXPECT_EQ(refused.output.find("buffer '"), std::string::npos) << refused.output;
    EXPECT_EQ(std::count(refused.output.begin(), refused.output.end(), '\n'), 1) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "stats.json"));

    std::vector<std::string> enough = render_args(dir, "cornell-box", 256, method);
    enough.insert(enough.end(),
                  {"--device-memory", std::to_string(static_cast<int>(std::ceil(peak)))});
    const test::CommandResult rendered = test::run_radcache(enough);
    EXPECT_EQ(rendered.exit_code, 0) << rendered.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));
}

// A caching method's figure is the least it needs: refused up front when that does not fit
// ("at least", naming what it leaves out); when it fits, what its records add is still refused
// buffer by buffer, before the driver is asked, and nothing is written.
TEST(DeviceMemoryLimit, ACachingMethodIsRefusedUpFrontOrWhenItsCacheGrows) {
    const auto dir = test::scratch_dir("memory_need_cache");
    const std::vector<std::string> ic = {"--method", "ic", "--ic-rays", "1024"};
    std::vector<std::string> up_front = render_args(dir, "cornell-box", 256, ic);
    up_front.insert(up_front.end(), {"--device-memory", "4"});
    const test::CommandResult refused = test::run_radcache(up_front);
    EXPECT_EQ(refused.exit_code, 1) << refused.output;
    EXPECT_GT(needed_mebibytes(refused.output), 4.0) << refused.output;
    EXPECT_NE(refused.output.find("the render needs at least"), std::string::npos)
        << refused.output;
    EXPECT_NE(refused.output.find("then the cache records and their batches"), std::string::npos)
        << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));

    // 32 x 32 needs about 0.3 MiB before its records; a batch of 1024-ray records is 14 MiB.
    std::vector<std::string> growing = render_args(dir, "cornell-box", 32, ic);
    growing.insert(growing.end(), {"--device-memory", "1"});
    const test::CommandResult grown = test::run_radcache(growing);
    EXPECT_EQ(grown.exit_code, 1) << grown.output;
    EXPECT_NE(grown.output.find("error: buffer 'ic_"), std::string::npos) << grown.output;
    EXPECT_NE(grown.output.find("MiB this run holds, more than the 1.00 MiB of --device-memory"),
              std::string::npos)
        << grown.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

}  // namespace
}  // namespace rc
