// Rendering on several devices (issue 14; `--device all`, `--device P:D,P:D`): with PoCL
// exposing two CPU devices (POCL_DEVICES="pthread pthread"), the path tracer's image is bitwise
// the single-device image whatever the devices' order, chunking and work-group size, both devices
// render a share that adds up to the image (stats); so are the grid methods' images, their
// photons shared; methods that render on one device, a device
// named twice, an empty entry, --time and intermediate images are refused with exit status 2 and
// no output; a device that fails mid-render stops the render with one line naming that device and
// the call, and no output file. Skipped where PoCL does not give two devices.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "device/fault_injection.h"
#include "image/image_io.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

const std::string kTwoDevices = "POCL_DEVICES=pthread pthread";

bool two_devices() {
    const test::CommandResult result = test::run_radcache({"devices"}, {kTwoDevices});
    return result.exit_code == 0 && result.output.find("0:1") != std::string::npos;
}

std::string cornell() {
    return (test::source_dir() / "scenes" / "cornell-box" / "scene.json").string();
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// `radcache render` of the Cornell box at 40 x 36, 8 spp with `options` into dir/name.exr
// (every layer) and its stats; exit status 0 expected.
nlohmann::json render(const std::filesystem::path& dir, const std::string& name,
                      const std::vector<std::string>& options) {
    std::vector<std::string> args = {"render",   cornell(),
                                     "--width",  "40",
                                     "--height", "36",
                                     "--spp",    "8",
                                     "-o",       (dir / (name + ".exr")).string(),
                                     "--stats",  (dir / (name + ".json")).string(),
                                     "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CommandResult result = test::run_radcache(args, {kTwoDevices});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / (name + ".json")));
    return stats.contains("frames") ? stats["frames"][0] : stats;
}

TEST(MultiDevice, PathTracerImageIsTheOneDeviceImageWhateverTheSplit) {
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_pt");
    render(dir, "one", {"--device", "0:0"});
    const Image expected = read_image(dir / "one.exr");
    for (const auto& [name, options] :
         std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"pair", {"--device", "0:0,0:1"}},
             {"all", {"--device", "all"}},
             {"swapped", {"--device", "0:1, 0:0", "--max-chunk", "100", "--local-size", "8"}}}) {
        const nlohmann::json stats = render(dir, name, options);
        EXPECT_TRUE(same_pixels(read_image(dir / (name + ".exr")), expected)) << name;
        const nlohmann::json& devices = stats.at("devices");
        ASSERT_EQ(devices.size(), 2u) << name;
        size_t pixels = 0;
        for (const nlohmann::json& d : devices) {
            EXPECT_GT(d.at("chunks").get<size_t>(), 0u) << name;
            EXPECT_GT(d.at("rays").get<uint64_t>(), 0u) << name;
            pixels += d.at("pixels").get<size_t>();
        }
        EXPECT_EQ(pixels, 40u * 36u) << name;
    }
}

// The irradiance vector grid's photons shared by the two devices: the grid's fixed-point sums are
// added exactly, so `ivg` and `ivg-gather` images are bitwise the one-device images, and both
// devices traced photons that add up to the grid's.
TEST(MultiDevice, GridMethodsImageIsTheOneDeviceImage) {
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_ivg");
    for (const std::string method : {"ivg", "ivg-gather"}) {
        render(dir, method + "_one", {"--method", method, "--device", "0:0"});
        const nlohmann::json stats =
            render(dir, method + "_two", {"--method", method, "--device", "0:1,0:0"});
        EXPECT_TRUE(same_pixels(read_image(dir / (method + "_two.exr")),
                                read_image(dir / (method + "_one.exr"))))
            << method;
        const nlohmann::json& grid = stats.at("grid");
        ASSERT_EQ(grid.at("devices").size(), 2u) << method;
        uint64_t photons = 0;
        for (const nlohmann::json& d : grid.at("devices")) {
            EXPECT_GT(d.at("batches").get<size_t>(), 0u) << method;
            photons += d.at("photons").get<uint64_t>();
        }
        EXPECT_EQ(photons, grid.at("photons").get<uint64_t>()) << method;
    }
}

TEST(MultiDevice, WhatRendersOnOneDeviceIsRefusedByName) {
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_refused");
    const std::string out = (dir / "x.exr").string();
    struct Case {
        std::vector<std::string> options;
        std::string names;
    };
    for (const Case& c : std::vector<Case>{
             {{"--method", "ic", "--device", "all"}, "--method ic renders on one"},
             {{"--method", "rc", "--device", "0:0,0:1"}, "--method rc renders on one"},
             {{"--device", "0:0,0:0"}, "twice"},
             {{"--device", "0:0,"}, "empty entry"},
             {{"--device", "0:0,7:7"}, "7:7"},
             {{"--device", "all", "--time", "1"}, "--time"},
             {{"--device", "all", "--save-every-pow2"}, "--save-every-pow2"}}) {
        std::vector<std::string> args = {"render",   cornell(), "--width", "8",
                                         "--height", "8",       "-o",      out};
        args.insert(args.end(), c.options.begin(), c.options.end());
        const test::CommandResult result = test::run_radcache(args, {kTwoDevices});
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find(c.names), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.names;
    }
}

// Commands other than render use one device: a list or `all` is refused by name (exit 2).
TEST(MultiDevice, OtherCommandsRefuseSeveralDevices) {
    for (const std::string spec : {"all", "0:0,0:1"}) {
        const test::CommandResult result =
            test::run_radcache({"warmup", "--method", "pt", "--device", spec}, {kTwoDevices});
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find("names several devices"), std::string::npos) << result.output;
    }
}

// In this process (the fault injection is in-process): the 20th kernel launch of the render
// fails, on whichever device made it.
TEST(MultiDevice, ADeviceThatFailsMidRenderStopsTheRenderNamingIt) {
    setenv("POCL_DEVICES", "pthread pthread", 1);  // before this process's first OpenCL call
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_fault");
    const auto out = dir / "x.exr";
    arm_device_fault("clEnqueueNDRangeKernel", 20, -5);  // CL_OUT_OF_RESOURCES
    int exit_code = 0;
    std::string message;
    try {
        exit_code = run_render_command({cornell(), "--width", "40", "--height", "36", "--spp", "8",
                                        "--device", "0:0,0:1", "-o", out.string(), "--quiet"});
    } catch (const Error& error) {
        exit_code = error.exit_code();
        message = error.what();
    }
    const bool fired = device_fault_fired();
    disarm_device_fault();
    ASSERT_TRUE(fired);
    EXPECT_EQ(exit_code, 1);
    EXPECT_TRUE(message.rfind("device 0:0 (", 0) == 0 || message.rfind("device 0:1 (", 0) == 0)
        << message;
    EXPECT_NE(message.find("clEnqueueNDRangeKernel"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_FALSE(std::filesystem::exists(out));
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        ADD_FAILURE() << "left behind: " << entry.path();
    }
}

}  // namespace
}  // namespace rc
