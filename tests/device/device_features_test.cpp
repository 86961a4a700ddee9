// What `radcache devices` says each device lacks (host/device/device_features.h), against what the
// implementations are known to do: PoCL's CPU device defines cl_khr_fp64 and
// cl_khr_int64_base_atomics in its compiler and its profiling events measure; Mesa's rusticl
// (llvmpipe, where installed) lists cl_khr_int64_base_atomics but its compiler does not define
// it, gives every launch 1 ns, and ends a work item's loops after 65535 iterations in all.
#include "device/device_features.h"

#include <gtest/gtest.h>

#include <string>

#include "device/context.h"
#include "test_support.h"

namespace rc {
namespace {

TEST(DeviceFeatures, PoclDefinesWhatTheKernelsUseAndItsEventsMeasure) {
    Context& context = test::shared_context();
    if (context.device().platform_name != "Portable Computing Language") {
        GTEST_SKIP() << "the suite's device is not PoCL's: " << context.device().platform_name;
    }
    const DeviceFeatures features = probe_device_features(context);
    EXPECT_TRUE(features.fp64);
    EXPECT_TRUE(features.int64_atomics);
    EXPECT_TRUE(features.profiling);
    EXPECT_FALSE(features.loop_cap.has_value());
    EXPECT_TRUE(lacking(features).empty());
}

// The loop probe against the host's own steps of its LCG: PoCL runs all kLoopProbeIterations (no
// cap); a cap the probe reports is named with its figure and what radcache does about it.
TEST(DeviceFeatures, TheLoopProbeFindsNoCapOnPoclAndACapIsNamed) {
    Context& context = test::shared_context();
    if (context.device().platform_name == "Portable Computing Language") {
        EXPECT_EQ(probe_loop_cap(context), std::nullopt);
    }
    DeviceFeatures capped;
    capped.fp64 = capped.int64_atomics = capped.profiling = true;
    capped.loop_cap = 65535;
    const std::vector<std::string> lacks = lacking(capped);
    ASSERT_EQ(lacks.size(), 1u);
    EXPECT_NE(lacks[0].find("65535 iterations"), std::string::npos) << lacks[0];
    EXPECT_NE(lacks[0].find("--allow-loop-cap"), std::string::npos) << lacks[0];
}

TEST(DeviceFeatures, EachLackNamesTheExtensionAndWhatRadcacheDoesWithoutIt) {
    const std::vector<std::string> lacks = lacking(DeviceFeatures{});
    ASSERT_EQ(lacks.size(), 3u);
    EXPECT_NE(lacks[0].find("cl_khr_fp64"), std::string::npos);
    EXPECT_NE(lacks[1].find("cl_khr_int64_base_atomics"), std::string::npos);
    EXPECT_NE(lacks[1].find("two 32-bit atomics"), std::string::npos);
    EXPECT_NE(lacks[2].find("profiling"), std::string::npos);
}

// `radcache devices` with rusticl's CPU device enabled: its line names the 64-bit atomics its
// compiler does not define and the profiling that does not measure; PoCL's says nothing.
TEST(DeviceFeatures, RusticlsLacksAreListed) {
    const test::CommandResult result = test::run_radcache({"devices"}, {"RUSTICL_ENABLE=llvmpipe"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const size_t table_end = result.output.find("what each device lacks");
    ASSERT_NE(table_end, std::string::npos) << result.output;
    const size_t rusticl = result.output.find("rusticl");
    if (rusticl == std::string::npos || rusticl > table_end) {
        GTEST_SKIP() << "rusticl is not installed (mesa-opencl-icd)";
    }
    // The device's index: the start of its table row.
    const size_t row = result.output.rfind('\n', rusticl) + 1;
    const std::string spec = result.output.substr(row, result.output.find(' ', row) - row);
    const size_t line = result.output.find("\n" + spec + " ", table_end);
    ASSERT_NE(line, std::string::npos) << result.output;
    const std::string lacks =
        result.output.substr(line + 1, result.output.find('\n', line + 1) - line - 1);
    EXPECT_NE(lacks.find("cl_khr_int64_base_atomics"), std::string::npos) << lacks;
    EXPECT_NE(lacks.find("event profiling"), std::string::npos) << lacks;
    // gallivm's loop limiter (LP_MAX_TGSI_LOOP_ITERATIONS in Mesa), found by the probe.
    EXPECT_NE(lacks.find("loops past 65535 iterations"), std::string::npos) << lacks;
}

}  // namespace
}  // namespace rc
