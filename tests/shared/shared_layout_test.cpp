// Host and device agree on the layout of every shared struct: RC_SHARED_LAYOUTS
// (kernels/shared/types.h) and radiance caching's RC_RADIANCE_CACHE_LAYOUTS
// (kernels/shared/radiance_cache.h), SDRC's RC_SDRC_LAYOUTS (kernels/shared/sdrc.h), temporal
// caching's RC_TEMPORAL_LAYOUTS (kernels/shared/temporal.h) and irradiance decomposition's
// RC_DECOMP_LAYOUTS (kernels/shared/decomposition.h), each reported by its probe kernel.
#include <gtest/gtest.h>

#include "shared/decomposition.h"
#include "shared/radiance_cache.h"
#include "shared/sdrc.h"
#include "shared/temporal.h"
#include "shared/types.h"
#include "test_support.h"

namespace rc {
namespace {

struct Layouts {
    std::vector<unsigned> values;  // sizeof and offsetof, in the list's order
    std::vector<std::string> names;
};

// The host's figures of one layout list (an X-macro taking STRUCT and FIELD).
#define RC_HOST_LAYOUTS(LIST)               \
    [] {                                    \
        Layouts host;                       \
        LIST(RC_HOST_STRUCT, RC_HOST_FIELD) \
        return host;                        \
    }()
#define RC_HOST_STRUCT(type)                                            \
    host.values.push_back(static_cast<unsigned>(sizeof(shared::type))); \
    host.names.push_back("sizeof(" #type ")");
#define RC_HOST_FIELD(type, field)                                               \
    host.values.push_back(static_cast<unsigned>(offsetof(shared::type, field))); \
    host.names.push_back("offsetof(" #type ", " #field ")");

void expect_device_matches(const Layouts& host, const std::string& file,
                           const std::string& kernel_name) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel(file, kernel_name);
    Buffer<unsigned> out(context, host.values.size(), "layouts");
    out.fill_zero();
    context.launch(kernel, 1, out);
    const std::vector<unsigned> device = out.download();
    ASSERT_EQ(device.size(), host.values.size());
    for (size_t i = 0; i < host.values.size(); ++i) {
        EXPECT_EQ(device[i], host.values[i]) << host.names[i];
    }
}

TEST(SharedLayout, DeviceMatchesHost) {
    expect_device_matches(RC_HOST_LAYOUTS(RC_SHARED_LAYOUTS), "shared_layout_probe.cl",
                          "report_shared_layouts");
}

TEST(SharedLayout, RadianceCacheDeviceMatchesHost) {
    expect_device_matches(RC_HOST_LAYOUTS(RC_RADIANCE_CACHE_LAYOUTS), "radiance_cache/rc_probe.cl",
                          "rc_report_layouts");
}

TEST(SharedLayout, SdrcDeviceMatchesHost) {
    expect_device_matches(RC_HOST_LAYOUTS(RC_SDRC_LAYOUTS), "sdrc/sdrc_probe.cl",
                          "sdrc_report_layouts");
}

TEST(SharedLayout, DecompositionDeviceMatchesHost) {
    expect_device_matches(RC_HOST_LAYOUTS(RC_DECOMP_LAYOUTS), "decomposition/decomp_probe.cl",
                          "decomp_report_layouts");
}

TEST(SharedLayout, TemporalDeviceMatchesHost) {
    expect_device_matches(RC_HOST_LAYOUTS(RC_TEMPORAL_LAYOUTS), "temporal/tc_probe.cl",
                          "tc_report_layouts");
}

}  // namespace
}  // namespace rc
