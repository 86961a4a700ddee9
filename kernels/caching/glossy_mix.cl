// Entry kernels of a scene's materials served by different glossy caches in one render
// (host/methods/glossy_mix.h; DESIGN.md §6.4, §6.5): a cache's camera-sample queries restricted
// to the materials it serves, and the caches' glossy buffers merged into the one the render pass
// reads. Item index: begin + get_global_id(0). Each item writes its own entry only: the result
// does not depend on the launch's size.
#include "common/kernel_range.h"
#include "shared/radiance_cache.h"

// Item i: query i left to path tracing (order -1) unless served[its material] is nonzero (a
// query without a hit keeps its order, -1).
RC_KERNEL void rc_glossy_restrict(uint begin, uint end, __global const int* served,
                                  __global RcQuery* queries) {
    RC_RANGE_ITEM(i);
    const int material = queries[i].material;
    if (material >= 0 && served[material] == 0) {
        queries[i].order = -1;
    }
}

// Item i: entry i of `from` into `into` where `from`'s cache serves it (order >= 0); the caches
// serve disjoint sets of materials, so at most one buffer of a mix serves each entry.
RC_KERNEL void rc_glossy_merge(uint begin, uint end, __global const RcGlossySample* from,
                               __global RcGlossySample* into) {
    RC_RANGE_ITEM(i);
    if (from[i].order >= 0) {
        into[i] = from[i];
    }
}
