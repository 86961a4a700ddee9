// Entry kernels for tracing batches of rays (tests and `radcache bench rays`).
#include "common/bvh_traversal.h"
#include "common/kernel_range.h"

RC_KERNEL void trace_closest(uint begin, uint end, __global const Ray* rays,
                             __global const TraversalNode* nodes,
                             __global const Triangle* triangles, __global Hit* hits) {
    RC_RANGE_ITEM(i);
    hits[i] = rc_trace_closest(nodes, triangles, rays[i]);
}

RC_KERNEL void trace_any(uint begin, uint end, __global const Ray* rays,
                         __global const TraversalNode* nodes, __global const Triangle* triangles,
                         __global uint* occluded) {
    RC_RANGE_ITEM(i);
    occluded[i] = rc_trace_any(nodes, triangles, rays[i]) ? 1u : 0u;
}
