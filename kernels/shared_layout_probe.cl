// Test kernel (tests/shared/shared_layout_test.cpp): reports sizeof and offsetof of every shared
// struct as the device compiler lays them out, in the order of RC_SHARED_LAYOUTS.
#include "shared/types.h"

__kernel void report_shared_layouts(uint begin, uint end, __global uint* out) {
    if (begin + (uint)get_global_id(0) != 0u || end == 0u) {
        return;
    }
    uint i = 0;
#define RC_REPORT_STRUCT(type) out[i++] = (uint)sizeof(type);
#define RC_REPORT_FIELD(type, field) out[i++] = (uint)rc_offsetof(type, field);
    RC_SHARED_LAYOUTS(RC_REPORT_STRUCT, RC_REPORT_FIELD)
#undef RC_REPORT_STRUCT
#undef RC_REPORT_FIELD
}
