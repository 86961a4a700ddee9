// Host and device agree on the layout of every shared struct: each header of kernels/shared/ lists
// its structs and fields in an X-macro (RC_SHARED_LAYOUTS in types.h, RC_RADIANCE_CACHE_LAYOUTS,
// RC_SDRC_LAYOUTS, RC_TEMPORAL_LAYOUTS, RC_DECOMP_LAYOUTS), whose sizes and offsets the host
// compiler gives here and the device's one probe kernel reports (kernels/shared_layout_probe.cl,
// built once per list with the list's name).
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

struct LayoutList {
    std::string name;  // the X-macro's
    Layouts host;
};

void PrintTo(const LayoutList& list, std::ostream* out) { *out << list.name; }

#define RC_LAYOUT_LIST(LIST) \
    LayoutList { #LIST, RC_HOST_LAYOUTS(LIST) }

const LayoutList kLayoutLists[] = {
    RC_LAYOUT_LIST(RC_SHARED_LAYOUTS), RC_LAYOUT_LIST(RC_RADIANCE_CACHE_LAYOUTS),
    RC_LAYOUT_LIST(RC_SDRC_LAYOUTS),   RC_LAYOUT_LIST(RC_TEMPORAL_LAYOUTS),
    RC_LAYOUT_LIST(RC_DECOMP_LAYOUTS),
};

class SharedLayout : public testing::TestWithParam<LayoutList> {};

TEST_P(SharedLayout, DeviceMatchesHost) {
    const LayoutList& list = GetParam();
    Context& context = test::shared_context();
    Kernel kernel =
        context.kernel("shared_layout_probe.cl", "report_layouts", "-DRC_LAYOUT_LIST=" + list.name);
    Buffer<unsigned> out(context, list.host.values.size(), "layouts");
    out.fill_zero();
    context.launch(kernel, 1, out);
    const std::vector<unsigned> device = out.download();
    ASSERT_EQ(device.size(), list.host.values.size());
    ASSERT_GT(device.size(), 1u);
    for (size_t i = 0; i < device.size(); ++i) {
        EXPECT_EQ(device[i], list.host.values[i]) << list.host.names[i];
    }
}

INSTANTIATE_TEST_SUITE_P(EveryHeader, SharedLayout, testing::ValuesIn(kLayoutLists),
                         [](const testing::TestParamInfo<LayoutList>& info) {
                             return info.param.name;
                         });

}  // namespace
}  // namespace rc
