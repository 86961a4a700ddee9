// Test kernels of SDRC's L-tree (tests/sdrc/sdrc_ltree_test.cpp). Item index: begin +
// get_global_id(0).
#include "common/kernel_range.h"
#include "sdrc/ltree.h"
#include "shared/sdrc.h"

// Item q: rc_ltree_query of record records[q]'s L-tree (trees[records[q]] over `nodes`) at
// queries[q] (x: u, y: v, z: radius). counts[q]: the samples found; sums[q]: xyz the weighted
// radiance sum, w the weight sum; found[q * capacity ...]: the first `capacity` found indices
// (relative to the record's first node), in the order the query found them.
RC_KERNEL void sdrc_query_probe(uint begin, uint end, __global const LTreeNode* nodes,
                                __global const SdrcTree* trees, __global const uint* records,
                                __global const float4* queries, uint capacity,
                                __global uint* counts, __global float4* sums,
                                __global uint* found) {
    RC_RANGE_ITEM(q);
    const float4 query = queries[q];
    LTreeFound result;
    result.radiance = (float3)(0.0f);
    result.weight = 0.0f;
    result.count = 0u;
    rc_ltree_query(nodes, trees[records[q]], query.x, query.y, query.z, &result,
                   found + (size_t)q * capacity, capacity);
    counts[q] = result.count;
    sums[q] = (float4)(result.radiance, result.weight);
}
