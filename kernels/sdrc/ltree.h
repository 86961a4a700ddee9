// The L-tree's range query on the device (SDRC §4.4, Figure 2; DESIGN.md §6.5): every radiance
// sample of a record within the query radius r_d of a point of D, weighted by
// w_d = 1 - (|w_k - w_j| / r_d)^2, over the record's kd-tree (median order, kernels/shared/sdrc.h)
// and then its buffer of inserted samples.
#pragma once

#include "shared/sdrc.h"

// What a range query found: sum w_d L (rgb), sum w_d, and how many samples.
typedef struct LTreeFound {
    float3 radiance;
    float weight;
    uint count;
} LTreeFound;

// One node against the query point (u, v) and radius: its weight added when it lies strictly
// within the radius; its index (relative to the tree's first node) written to found_indices when
// that is not 0 and there is room (tests).
RC_FUNC void rc_ltree_visit(LTreeNode node, uint index, float u, float v, float radius,
                            LTreeFound* found, RC_GLOBAL uint* found_indices, uint capacity) {
    if ((node.position & RC_LTREE_EMPTY) != 0u) {
        return;
    }
    const float du = rc_ltree_centre(rc_ltree_node_u(node.position)) - u;
    const float dv = rc_ltree_centre(rc_ltree_node_v(node.position)) - v;
    const float d2 = du * du + dv * dv;
    const float r2 = radius * radius;
    if (!(d2 < r2)) {
        return;
    }
    const float w = 1.0f - d2 / r2;
    float r, g, b;
    rc_rgbe_decode(node.radiance, &r, &g, &b);
    found->radiance += w * (float3)(r, g, b);
    found->weight += w;
    if (found_indices != 0 && found->count < capacity) {
        found_indices[found->count] = index;
    }
    found->count += 1u;
}

// The range query of record `tree` at (u, v) with `radius` (SDRC §4.4: T_i(w_j), the samples with
// w_d > 0), accumulated into *found. The kd-tree is walked with a stack of node ranges; a subtree
// is skipped when the split plane proves every node in it farther than the radius along the
// split axis.
RC_FUNC void rc_ltree_query(RC_GLOBAL const LTreeNode* nodes, SdrcTree tree, float u, float v,
                            float radius, LTreeFound* found, RC_GLOBAL uint* found_indices,
                            uint capacity) {
    RC_GLOBAL const LTreeNode* own = nodes + tree.first_node;
    uint stack_lo[RC_LTREE_STACK];
    uint stack_hi[RC_LTREE_STACK];
    int top = 0;
    if (tree.tree_nodes > 0u) {
        stack_lo[0] = 0u;
        stack_hi[0] = tree.tree_nodes;
        top = 1;
    }
    while (top > 0) {
        --top;
        uint lo = stack_lo[top];
        uint hi = stack_hi[top];
        while (lo < hi) {
            const uint mid = lo + (hi - lo) / 2u;
            const LTreeNode node = own[mid];
            rc_ltree_visit(node, mid, u, v, radius, found, found_indices, capacity);
            const uint axis = (node.position >> RC_LTREE_AXIS_SHIFT) & 1u;
            const float split = rc_ltree_centre(axis == 0u ? rc_ltree_node_u(node.position)
                                                           : rc_ltree_node_v(node.position));
            const float q = axis == 0u ? u : v;
            const bool left = q - radius <= split;   // [lo, mid) lies at or below the split
            const bool right = q + radius >= split;  // (mid, hi) at or above it
            if (left && right && mid + 1u < hi && top < RC_LTREE_STACK) {
                stack_lo[top] = mid + 1u;
                stack_hi[top] = hi;
                ++top;
                hi = mid;
            } else if (left) {
                hi = mid;
            } else {
                lo = mid + 1u;
            }
        }
    }
    for (uint k = 0u; k < tree.buffer_nodes; ++k) {
        const uint index = tree.tree_nodes + k;
        rc_ltree_visit(own[index], index, u, v, radius, found, found_indices, capacity);
    }
}
