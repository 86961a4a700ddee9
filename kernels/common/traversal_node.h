// The node type of the BVH layout this program is built for: the host's Context passes
// -DRC_BVH_LAYOUT (host/device/bvh_layout.h, docs/bvh.md).
#pragma once

#include "shared/types.h"

#if RC_BVH_LAYOUT == RC_BVH_LAYOUT_WIDE
typedef WideBvhNode TraversalNode;
#elif RC_BVH_LAYOUT == RC_BVH_LAYOUT_BVH4
typedef BvhNode TraversalNode;
#else
#error "RC_BVH_LAYOUT names no BVH layout"
#endif
