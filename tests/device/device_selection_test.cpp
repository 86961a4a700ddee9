// Device selection: by index, by name substring, by environment; bad specs and a machine
// without OpenCL platforms (whatever the ICD loader) give exit status 2 with the device list or the
// package to install.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include "device/device_list.h"
#include "device/fault_injection.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

std::string toggled_case(std::string text) {
    for (char& c : text) {
        c = std::isupper(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c))
                                                        : static_cast<char>(std::toupper(c));
    }
    return text;
}

TEST(DeviceSelection, DevicesCommandListsEveryDevice) {
    const auto devices = list_devices();
    const test::CommandResult result = test::run_radcache({"devices"});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    for (const DeviceInfo& device : devices) {
        EXPECT_NE(result.output.find(device.spec()), std::string::npos);
        EXPECT_NE(result.output.find(device.name), std::string::npos);
        EXPECT_NE(result.output.find(device.opencl_c_version), std::string::npos);
    }
    EXPECT_NE(result.output.find("units"), std::string::npos);
}

TEST(DeviceSelection, SelectsByIndexAndByCaseInsensitiveSubstring) {
    const auto devices = list_devices();
    const DeviceInfo& last = devices.back();
    EXPECT_EQ(select_device(devices, last.spec()).device, last.device);
    const std::string middle = last.name.substr(last.name.size() / 4, last.name.size() / 2);
    ASSERT_FALSE(middle.empty());
    const DeviceInfo chosen = select_device(devices, toggled_case(middle));
    std::string lower_name = chosen.name;
    std::string lower_middle = middle;
    std::transform(lower_name.begin(), lower_name.end(), lower_name.begin(), ::tolower);
    std::transform(lower_middle.begin(), lower_middle.end(), lower_middle.begin(), ::tolower);
    EXPECT_NE(lower_name.find(lower_middle), std::string::npos);
}

// A platform's name chooses among devices of one processor name (PoCL's and Intel's runtime's
// CPU device both carry it): every platform's name picks a device of that platform.
TEST(DeviceSelection, SelectsByPlatformName) {
    const auto devices = list_devices();
    for (const DeviceInfo& device : devices) {
        const DeviceInfo chosen =
            select_device(devices, toggled_case(device.platform_name + " " + device.name));
        EXPECT_EQ(chosen.platform_name + " " + chosen.name,
                  device.platform_name + " " + device.name);
        EXPECT_EQ(select_device(devices, device.platform_name).platform_name, device.platform_name);
    }
}

TEST(DeviceSelection, DefaultPrefersAGpuThenACpu) {
    const auto devices = list_devices();
    const DeviceInfo chosen = select_device(devices, "");
    const bool any_gpu =
        std::any_of(devices.begin(), devices.end(), [](const DeviceInfo& d) { return d.is_gpu; });
    if (any_gpu) {
        EXPECT_TRUE(chosen.is_gpu);
    } else {
        EXPECT_TRUE(chosen.is_cpu || !std::any_of(devices.begin(), devices.end(),
                                                  [](const DeviceInfo& d) { return d.is_cpu; }));
    }
}

TEST(DeviceSelection, UnknownSpecThrowsWithTheDeviceList) {
    const auto devices = list_devices();
    try {
        select_device(devices, "no-such-device-xyz");
        FAIL() << "no error";
    } catch (const Error& error) {
        EXPECT_EQ(error.exit_code(), kExitUsage);
        EXPECT_NE(std::string(error.what()).find("no-such-device-xyz"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find(devices[0].name), std::string::npos);
        EXPECT_NE(std::string(error.what()).find(devices[0].spec()), std::string::npos);
        // One line: the devices named in it, not a table after it.
        EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    }
    EXPECT_THROW(select_device(devices, "97:3"), Error);
}

TEST(DeviceSelection, RenderWithBadDeviceExitsTwoListingDevicesAndWritesNothing) {
    const auto output = test::scratch_dir("device_selection") / "out.png";
    const test::CommandResult result = test::run_radcache(
        {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "-o",
         output.string(), "--device", "no-such-device-xyz"});
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("no-such-device-xyz"), std::string::npos);
    EXPECT_NE(result.output.find(list_devices()[0].name), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(output));
}

TEST(DeviceSelection, EnvironmentVariableSelectsAndIsReportedWhenBad) {
    const auto output = test::scratch_dir("device_env") / "out.png";
    const std::string scene = (test::source_dir() / "scenes/cornell-box/scene.json").string();
    test::CommandResult bad = test::run_radcache(
        {"render", scene, "-o", output.string(), "--width", "8", "--height", "8"},
        {"RADCACHE_DEVICE=no-such-device-xyz"});
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("RADCACHE_DEVICE"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(output));

    const auto devices = list_devices();
    test::CommandResult good =
        test::run_radcache({"render", scene, "-o", output.string(), "--width", "8", "--height", "8",
                            "--spp", "1", "--quiet"},
                           {"RADCACHE_DEVICE=" + toggled_case(devices[0].name.substr(0, 6))});
    EXPECT_EQ(good.exit_code, 0) << good.output;
    EXPECT_TRUE(std::filesystem::exists(output));
}

TEST(DeviceSelection, NoPlatformNamesThePackageAndExitsTwo) {
    // Whatever the ICD loader: its platform query fails as a loader with no platform answers
    // (CL_PLATFORM_NOT_FOUND_KHR), through the device fault injection.
    arm_device_fault("clGetPlatformIDs", 1, -1001);
    try {
        list_devices();
        disarm_device_fault();
        FAIL() << "no error";
    } catch (const Error& error) {
        disarm_device_fault();
        const std::string message = error.what();
        EXPECT_EQ(error.exit_code(), 2);
        EXPECT_NE(message.find("pocl-opencl-icd"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(DeviceSelection, NoPlatformThroughTheCommandLineExitsTwoWithOneLine) {
    // An empty vendor directory hides every platform from ocl-icd's loader; the Khronos loader
    // ignores it (the test above covers the message whatever the loader).
    const auto empty = test::scratch_dir("no_icd");
    const test::CommandResult result =
        test::run_radcache({"devices"}, {"OCL_ICD_VENDORS=" + empty.string()});
    if (result.exit_code == 0) {
        GTEST_SKIP() << "this ICD loader ignores OCL_ICD_VENDORS: " << result.output;
    }
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("pocl-opencl-icd"), std::string::npos) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
}

}  // namespace
}  // namespace rc
