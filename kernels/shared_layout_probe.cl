// Test kernel (tests/shared/shared_layout_test.cpp): reports sizeof and offsetof of every struct
// and field of one shared header's layout list, an X-macro RC_<NAME>_LAYOUTS(STRUCT, FIELD) named
// by the build option -DRC_LAYOUT_LIST=RC_<NAME>_LAYOUTS, as the device compiler lays them out,
// in the list's order. One probe for every header of kernels/shared/ that has such a list.
#include "shared/decomposition.h"
#include "shared/radiance_cache.h"
#include "shared/sdrc.h"
#include "shared/temporal.h"
#include "shared/types.h"

RC_KERNEL void report_layouts(uint begin, uint end, __global uint* out) {
    if (begin + (uint)get_global_id(0) != 0u || end == 0u) {
        return;
    }
    uint i = 0;
#define RC_REPORT_STRUCT(type) out[i++] = (uint)sizeof(type);
#define RC_REPORT_FIELD(type, field) out[i++] = (uint)rc_offsetof(type, field);
    RC_LAYOUT_LIST(RC_REPORT_STRUCT, RC_REPORT_FIELD)
#undef RC_REPORT_STRUCT
#undef RC_REPORT_FIELD
}
