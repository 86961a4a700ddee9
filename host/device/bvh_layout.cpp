#include "device/bvh_layout.h"

namespace rc {

const char* bvh_layout_name(BvhLayout layout) {
    return layout == BvhLayout::kWide ? "wide" : "bvh4";
}

std::optional<BvhLayout> parse_bvh_layout(const std::string& name) {
    for (BvhLayout layout : kBvhLayouts) {
        if (name == bvh_layout_name(layout)) {
            return layout;
        }
    }
    return std::nullopt;
}

BvhLayout default_bvh_layout() { return BvhLayout::kWide; }

}  // namespace rc
