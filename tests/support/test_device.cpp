#include "test_device.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "device/device_list.h"
#include "util/error.h"

namespace rc::test {

std::string test_device_spec() {
    const char* spec = std::getenv("RADCACHE_TEST_DEVICE");
    return spec == nullptr ? std::string() : std::string(spec);
}

namespace {

// Before any test: the device $RADCACHE_TEST_DEVICE names, printed, or every test skipped.
class TestDeviceEnvironment : public ::testing::Environment {
   public:
    void SetUp() override {
        const std::string spec = test_device_spec();
        if (spec.empty()) {
            return;
        }
        std::string why;
        try {
            const DeviceInfo device = select_device(list_devices(), spec);
            std::printf("RADCACHE_TEST_DEVICE=%s: the tests run on %s (%s, %s)\n", spec.c_str(),
                        device.spec().c_str(), device.platform_name.c_str(), device.name.c_str());
            // Renders there (in this process and through the command line) go ahead where the
            // device ends loops early (host/device/device_features.h): the tests' own bounds
            // judge what it computes.
            setenv("RADCACHE_ALLOW_LOOP_CAP", "1", 1);
            return;
        } catch (const Error& error) {
            why = error.what();
        }
        // CTest counts a test as skipped when its output holds gtest's "[  SKIPPED ]", which
        // gtest does not print for a skip in a global environment.
        std::printf("[  SKIPPED ] every test: RADCACHE_TEST_DEVICE=%s names no device here\n",
                    spec.c_str());
        GTEST_SKIP() << why
                     << " (Mesa's rusticl: mesa-opencl-icd, and RUSTICL_ENABLE=llvmpipe for its "
                        "CPU device)";
    }
};

[[maybe_unused]] ::testing::Environment* const kRegistered =
    ::testing::AddGlobalTestEnvironment(new TestDeviceEnvironment);

}  // namespace

}  // namespace rc::test
