// The work item of a range launch: every entry kernel takes `uint begin, uint end` first and its
// items are begin + get_global_id(0); the host rounds the global size up to whole work groups, so
// the items at or past `end` do nothing.
#pragma once

#include "shared/compat.h"  // RC_KERNEL

// Declares `const uint item` (the entry this work item computes) and returns from the kernel when
// it lies at or past `end`.
#define RC_RANGE_ITEM(item)                           \
    const uint item = begin + (uint)get_global_id(0); \
    if (item >= end) {                                \
        return;                                       \
    }
