// Tests that run once per BVH layout: INSTANTIATE_TEST_SUITE_P(Layouts, Suite, kAllBvhLayouts,
// bvh_layout_test_name).
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "device/bvh_layout.h"

namespace rc {

// gtest prints a layout parameter by its name.
inline void PrintTo(BvhLayout layout, std::ostream* out) { *out << bvh_layout_name(layout); }

}  // namespace rc

namespace rc::test {

inline const auto kAllBvhLayouts = ::testing::ValuesIn(kBvhLayouts);

inline std::string bvh_layout_test_name(const ::testing::TestParamInfo<BvhLayout>& info) {
    return bvh_layout_name(info.param);
}

}  // namespace rc::test
