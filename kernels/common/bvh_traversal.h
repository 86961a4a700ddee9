// Closest-hit and any-hit queries over the BVH in the layout this program is built for
// (RC_BVH_LAYOUT, docs/bvh.md): every kernel traces through these two functions.
#pragma once

#include "common/bvh_ray.h"
#include "common/traversal_node.h"
#include "shared/types.h"

#if RC_BVH_LAYOUT == RC_BVH_LAYOUT_WIDE
#include "common/wide_bvh_traversal.h"
#else
#include "common/bvh4_traversal.h"
#endif

// Sets *hit to "nothing in the ray's interval" and returns whether the ray is traced at all.
RC_FUNC bool rc_begin_trace(Ray ray, Hit* hit) {
    hit->t = ray.direction.w;
    hit->primitive = RC_NO_HIT;
    hit->u = 0.0f;
    hit->v = 0.0f;
    return rc_ray_is_traceable(ray);
}

// The closest hit in (tmin, tmax]; among hits at the same distance, the smallest primitive index.
RC_FUNC Hit rc_trace_closest(RC_GLOBAL const TraversalNode* nodes,
                             RC_GLOBAL const Triangle* triangles, Ray ray) {
    Hit hit;
    if (rc_begin_trace(ray, &hit)) {
        const TraversalRay r = rc_traversal_ray(ray);
#if RC_BVH_LAYOUT == RC_BVH_LAYOUT_WIDE
        rc_traverse_wide_closest(nodes, &r, &hit);
#else
        rc_traverse_bvh4(nodes, triangles, &r, false, &hit);
#endif
    }
    return hit;
}

// Whether anything is hit in (tmin, tmax].
RC_FUNC bool rc_trace_any(RC_GLOBAL const TraversalNode* nodes, RC_GLOBAL const Triangle* triangles,
                          Ray ray) {
    Hit hit;
    if (!rc_begin_trace(ray, &hit)) {
        return false;
    }
    const TraversalRay r = rc_traversal_ray(ray);
#if RC_BVH_LAYOUT == RC_BVH_LAYOUT_WIDE
    return rc_traverse_wide_any(nodes, &r, &hit);
#else
    return rc_traverse_bvh4(nodes, triangles, &r, true, &hit);
#endif
}
