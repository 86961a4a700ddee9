// The BVH layout a device's programs traverse (docs/bvh.md). It is chosen once, when the Context
// is made (--bvh, else default_bvh_layout()), and every program is built for it
// (-DRC_BVH_LAYOUT); the BVH is then built and uploaded in the same layout.
#pragma once

#include <optional>
#include <string>

#include "shared/types.h"

namespace rc {

enum class BvhLayout {
    kBvh4 = RC_BVH_LAYOUT_BVH4,  // 4-wide, float child boxes (128-byte nodes)
    kWide = RC_BVH_LAYOUT_WIDE,  // 8-wide, quantised child boxes (80-byte nodes)
};

inline constexpr BvhLayout kBvhLayouts[] = {BvhLayout::kBvh4, BvhLayout::kWide};

// "bvh4" or "wide", the names --bvh takes.
const char* bvh_layout_name(BvhLayout layout);
std::optional<BvhLayout> parse_bvh_layout(const std::string& name);

// The layout a device gets unless --bvh names one: the wide layout on every device type
// (docs/bvh.md: measured on PoCL; on GPUs it is the layout Ylitie et al. measured fastest).
BvhLayout default_bvh_layout();

}  // namespace rc
