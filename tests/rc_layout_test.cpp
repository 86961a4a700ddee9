// Host and device agree on the layout of radiance caching's shared structs
// (kernels/shared/radiance_cache.h).
#include <gtest/gtest.h>

#include "shared/radiance_cache.h"
#include "test_support.h"

namespace rc {
namespace {

TEST(RadianceCacheLayout, DeviceMatchesHost) {
    std::vector<unsigned> host;
    std::vector<std::string> names;
#define RC_HOST_STRUCT(type)                                     \
    host.push_back(static_cast<unsigned>(sizeof(shared::type))); \
    names.push_back("sizeof(" #type ")");
#define RC_HOST_FIELD(type, field)                                        \
    host.push_back(static_cast<unsigned>(offsetof(shared::type, field))); \
    names.push_back("offsetof(" #type ", " #field ")");
    RC_RADIANCE_CACHE_LAYOUTS(RC_HOST_STRUCT, RC_HOST_FIELD)
#undef RC_HOST_STRUCT
#undef RC_HOST_FIELD

    Context& context = test::shared_context();
    Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_report_layouts");
    Buffer<unsigned> out(context, host.size(), "layouts");
    out.fill_zero();
    context.launch(kernel, 1, out);
    const std::vector<unsigned> device = out.download();
    ASSERT_EQ(device.size(), host.size());
    for (size_t i = 0; i < host.size(); ++i) {
        EXPECT_EQ(device[i], host[i]) << names[i];
    }
}

}  // namespace
}  // namespace rc
