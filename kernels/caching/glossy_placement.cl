// Entry kernels of the glossy caches' record placement (host/methods/glossy_placement.h): which
// camera samples a glossy cache serves, and which of them no record covers yet. Shared by
// radiance caching and SDRC (DESIGN.md §6.4, §6.5). Item index: begin + get_global_id(0).
#include "caching/irradiance_records.h"
#include "common/kernel_range.h"
#include "shared/radiance_cache.h"

// Item i: query i appended to `served` (counted in counts[0], in any order) when its order is
// positive (the records serve it); counts[1] counts the queries with a specular lobe the cache
// serves (order >= 0), counts[2] those left to Monte Carlo (order 0).
RC_KERNEL void rc_served_queries(uint begin, uint end, __global const RcQuery* queries,
                                 __global uint* served, __global uint* counts) {
    RC_RANGE_ITEM(i);
    const int order = queries[i].order;
    if (order >= 0) {
        atomic_inc(&counts[1]);
    }
    if (order == 0) {
        atomic_inc(&counts[2]);
    }
    if (order > 0) {
        served[atomic_inc(&counts[0])] = i;
    }
}

// Item k: queries[indices[k]] into selected[k].
RC_KERNEL void rc_select_queries(uint begin, uint end, __global const RcQuery* queries,
                                 __global const uint* indices, __global RcQuery* selected) {
    RC_RANGE_ITEM(k);
    selected[k] = queries[indices[k]];
}

// Item q: query candidates[q]: appended to uncovered (counted in uncovered_count[0], in any order)
// when no record the world-space grid lists at it weighs it positively (TVCG 2005 §4.4, SDRC §4.4:
// S(p) is empty, a new record is needed).
RC_KERNEL void rc_uncovered(uint begin, uint end, float accuracy, float max_weight, RecordGrid grid,
                            __global const int* cell_start, __global const int* cell_records,
                            __global const Record* records, __global const RcQuery* queries,
                            __global const uint* candidates, __global uint* uncovered,
                            __global uint* uncovered_count) {
    RC_RANGE_ITEM(q);
    const RcQuery query = queries[candidates[q]];
    const int cell = rc_ic_grid_cell(&grid, query.position.xyz);
    if (cell >= 0) {
        for (int i = cell_start[cell]; i < cell_start[cell + 1]; ++i) {
            if (rc_record_weight(records + cell_records[i], query.position.xyz, query.normal.xyz,
                                 accuracy, max_weight) > 0.0f) {
                return;
            }
        }
    }
    uncovered[atomic_inc(&uncovered_count[0])] = candidates[q];
}

// Item q: query q, when the cache serves it (order > 0), marks every record the world-space grid
// lists at it that weighs it positively: used[r] = 1 (temporal caching replaces an expired record
// only while it still serves the image, the report's §5 "Replacement/Deletion Method"). Only the
// value 1 is written, so the result does not depend on the order.
RC_KERNEL void rc_records_used(uint begin, uint end, float accuracy, float max_weight,
                               RecordGrid grid, __global const int* cell_start,
                               __global const int* cell_records, __global const Record* records,
                               __global const RcQuery* queries, __global uint* used) {
    RC_RANGE_ITEM(q);
    const RcQuery query = queries[q];
    const int cell = query.order > 0 ? rc_ic_grid_cell(&grid, query.position.xyz) : -1;
    if (cell < 0) {
        return;
    }
    for (int i = cell_start[cell]; i < cell_start[cell + 1]; ++i) {
        const int r = cell_records[i];
        if (rc_record_weight(records + r, query.position.xyz, query.normal.xyz, accuracy,
                             max_weight) > 0.0f) {
            atomic_or(&used[r], 1u);
        }
    }
}
