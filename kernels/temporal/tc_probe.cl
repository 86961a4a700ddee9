// Test kernels of temporal caching (tests/temporal/temporal_kernels_test.cpp). Item index: begin +
// get_global_id(0).
#include "common/kernel_range.h"
#include "shared/temporal.h"
#include "temporal/tc_reprojection.h"

// Item q: the unshadowed irradiance from emitters[0 .. count) at point queries[2q] with normal
// queries[2q + 1], into out[q].
RC_KERNEL void tc_unshadowed_probe(uint begin, uint end, __global const TcEmitter* emitters,
                                   int count, __global const float4* queries,
                                   __global float4* out) {
    RC_RANGE_ITEM(q);
    out[q] = (float4)(rc_tc_unshadowed_irradiance(emitters, count, queries[2 * q].xyz,
                                                  queries[2 * q + 1].xyz),
                      0.0f);
}

// Item q: the cell of an M x N hemisphere of `layout` (RC_TC_CELLS_*) that local direction
// directions[q] passes through.
RC_KERNEL void tc_cell_probe(uint begin, uint end, int m, int n, int layout,
                             __global const float4* directions, __global int* out) {
    RC_RANGE_ITEM(q);
    out[q] = rc_tc_cell_of(directions[q].xyz, m, n, layout);
}
