// Closest-hit and any-hit traversal of the 4-wide BVH of float boxes (BvhNode, docs/bvh.md) with
// a private stack.
#pragma once

#include "common/bvh_ray.h"
#include "shared/types.h"

// Tests the four child boxes of a node against the ray over [tmin, tmax]; returns each child's
// entry distance in *t_enter and the lanes whose box is hit as -1 (OpenCL vector truth). The
// entry and exit planes are chosen by the direction's sign, so an unused lane's empty box
// (lower = +inf, upper = -inf) is never hit; a 0 * inf = NaN slab (ray in a box plane) drops out
// of fmax/fmin.
RC_FUNC int4 rc_intersect_node_boxes(RC_GLOBAL const BvhNode* node, const BoxRay* r, float tmin,
                                     float tmax, float4* t_enter) {
    const float4 near_x =
        ((r->negative_x ? node->upper_x : node->lower_x) - r->origin.x) * r->inv_direction.x;
    const float4 far_x =
        ((r->negative_x ? node->lower_x : node->upper_x) - r->origin.x) * r->inv_direction.x;
    const float4 near_y =
        ((r->negative_y ? node->upper_y : node->lower_y) - r->origin.y) * r->inv_direction.y;
    const float4 far_y =
        ((r->negative_y ? node->lower_y : node->upper_y) - r->origin.y) * r->inv_direction.y;
    const float4 near_z =
        ((r->negative_z ? node->upper_z : node->lower_z) - r->origin.z) * r->inv_direction.z;
    const float4 far_z =
        ((r->negative_z ? node->lower_z : node->upper_z) - r->origin.z) * r->inv_direction.z;
    const float4 near_t = fmax(fmax(near_x, near_y), fmax(near_z, (float4)(tmin)));
    const float4 far_t = fmin(fmin(far_x, far_y), fmin(far_z, (float4)(tmax))) * RC_BOX_FAR_SCALE;
    *t_enter = near_t;
    return near_t <= far_t;
}

// Traverses the BVH, children near to far. With any_hit set, stops at the first hit in the
// interval. Returns whether anything was hit; *hit holds the closest hit.
RC_FUNC bool rc_traverse_bvh4(RC_GLOBAL const BvhNode* nodes, RC_GLOBAL const Triangle* triangles,
                              const TraversalRay* ray, bool any_hit, Hit* hit) {
    int stack_child[RC_BVH_STACK_SIZE];
    int stack_count[RC_BVH_STACK_SIZE];
    float stack_t[RC_BVH_STACK_SIZE];
    int stack_size = 0;

    int child = 0;  // the root is inner node 0
    int count = 0;
    for (;;) {
        if (child >= 0) {
            // Inner node: order the hit children near to far, continue with the nearest and
            // push the others farthest first.
            RC_GLOBAL const BvhNode* node = nodes + child;
            float4 t_enter;
            const int4 hit_lanes =
                rc_intersect_node_boxes(node, &ray->box, ray->tmin, hit->t, &t_enter);
            const int4 lane_child = node->child;
            const int4 lane_count = node->count;
            int hit_child[4];
            int hit_count[4];
            float hit_t[4];
            int hits = 0;
#define RC_COLLECT_LANE(lane)                \
    if (hit_lanes.lane) {                    \
        float t = t_enter.lane;              \
        int j = hits++;                      \
        while (j > 0 && hit_t[j - 1] < t) {  \
            hit_t[j] = hit_t[j - 1];         \
            hit_child[j] = hit_child[j - 1]; \
            hit_count[j] = hit_count[j - 1]; \
            --j;                             \
        }                                    \
        hit_t[j] = t;                        \
        hit_child[j] = lane_child.lane;      \
        hit_count[j] = lane_count.lane;      \
    }
            RC_COLLECT_LANE(x)
            RC_COLLECT_LANE(y)
            RC_COLLECT_LANE(z)
            RC_COLLECT_LANE(w)
#undef RC_COLLECT_LANE
            if (hits > 0) {
                // hit_t is sorted far to near: push all but the last, descend into the last.
                for (int i = 0; i < hits - 1; ++i) {
                    stack_child[stack_size] = hit_child[i];
                    stack_count[stack_size] = hit_count[i];
                    stack_t[stack_size] = hit_t[i];
                    ++stack_size;
                }
                child = hit_child[hits - 1];
                count = hit_count[hits - 1];
                continue;
            }
        } else if (rc_intersect_leaf(triangles, (uint)~child, (uint)count, ray, any_hit, hit) &&
                   any_hit) {
            return true;
        }
        // Pop the next entry that may still hold a hit as near as the closest so far.
        bool found = false;
        while (stack_size > 0) {
            --stack_size;
            if (rc_may_hold_nearer_hit(stack_t[stack_size], hit)) {
                child = stack_child[stack_size];
                count = stack_count[stack_size];
                found = true;
                break;
            }
        }
        if (!found) {
            break;
        }
    }
    return hit->primitive != RC_NO_HIT;
}
