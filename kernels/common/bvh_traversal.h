// Closest-hit and any-hit traversal of the 4-wide BVH (docs/bvh.md) with a private stack.
// Box tests follow Ize, "Robust BVH Ray Traversal" (JCGT 2(2), 2013): the far distance is scaled
// by 1 + 2 gamma(3) so that rounding never culls a box the watertight triangle test would hit.
#pragma once

#include "common/ray_triangle.h"
#include "shared/types.h"

// 1 + 2 gamma(3), gamma(n) = n u / (1 - n u), u = 2^-24 (pbrt-v3 §3.9.1).
#define RC_BOX_FAR_SCALE 1.0000003576f

// A ray that traversal accepts: finite origin and direction, a non-zero direction, and an
// interval with tmin >= 0 and tmin <= tmax (tmax may be +inf). Any other ray hits nothing.
RC_FUNC bool rc_ray_is_traceable(Ray ray) {
    const float3 o = ray.origin.xyz;
    const float3 d = ray.direction.xyz;
    const float tmin = ray.origin.w;
    const float tmax = ray.direction.w;
    return all(isfinite(o)) && all(isfinite(d)) && any(d != 0.0f) && tmin >= 0.0f && tmin <= tmax &&
           !isnan(tmax);
}

// The per-ray part of the box test: origin, inverse direction and, per axis, whether the
// direction is negative (then the upper plane is entered first).
typedef struct BoxRay {
    float3 origin;
    float3 inv_direction;
    int negative_x, negative_y, negative_z;
} BoxRay;

RC_FUNC BoxRay rc_box_ray(float3 origin, float3 direction) {
    BoxRay r;
    r.origin = origin;
    r.inv_direction = 1.0f / direction;
    r.negative_x = r.inv_direction.x < 0.0f;
    r.negative_y = r.inv_direction.y < 0.0f;
    r.negative_z = r.inv_direction.z < 0.0f;
    return r;
}

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

// Tests the `count` triangles from `first`, shrinking hit->t to the nearest hit; returns whether
// any was hit (with any_hit set, stops at the first).
RC_FUNC bool rc_intersect_leaf(RC_GLOBAL const Triangle* triangles, int first, int count,
                               const WatertightRay* wray, float tmin, bool any_hit, Hit* hit,
                               int* closest) {
    bool found = false;
    for (int i = first; i < first + count; ++i) {
        float t, u, v;
        if (rc_intersect_triangle(wray, triangles[i].v0, triangles[i].v1, triangles[i].v2, tmin,
                                  hit->t, &t, &u, &v)) {
            hit->t = t;
            hit->u = u;
            hit->v = v;
            *closest = i;
            found = true;
            if (any_hit) {
                break;
            }
        }
    }
    return found;
}

// Traverses the BVH, children near to far. With any_hit set, stops at the first hit in the
// interval and reports only that something was hit. Returns whether anything was hit; *hit holds
// the closest hit.
RC_FUNC bool rc_traverse(RC_GLOBAL const BvhNode* nodes, RC_GLOBAL const Triangle* triangles,
                         Ray ray, bool any_hit, Hit* hit) {
    hit->t = ray.direction.w;
    hit->primitive = RC_NO_HIT;
    hit->u = 0.0f;
    hit->v = 0.0f;
    if (!rc_ray_is_traceable(ray)) {
        return false;
    }
    const float3 origin = ray.origin.xyz;
    const float3 direction = ray.direction.xyz;
    const BoxRay box_ray = rc_box_ray(origin, direction);
    const float tmin = ray.origin.w;
    const WatertightRay wray = rc_watertight_ray(origin, direction);

    int stack_child[RC_BVH_STACK_SIZE];
    int stack_count[RC_BVH_STACK_SIZE];
    float stack_t[RC_BVH_STACK_SIZE];
    int stack_size = 0;

    int child = 0;  // the root is inner node 0
    int count = 0;
    int closest = -1;
    for (;;) {
        if (child >= 0) {
            // Inner node: order the hit children near to far, continue with the nearest and
            // push the others farthest first.
            RC_GLOBAL const BvhNode* node = nodes + child;
            float4 t_enter;
            const int4 hit_lanes = rc_intersect_node_boxes(node, &box_ray, tmin, hit->t, &t_enter);
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
        } else if (rc_intersect_leaf(triangles, ~child, count, &wray, tmin, any_hit, hit,
                                     &closest) &&
                   any_hit) {
            hit->primitive = rc_as_uint(triangles[closest].v0.w);
            return true;
        }
        // Pop the next entry still nearer than the closest hit.
        bool found = false;
        while (stack_size > 0) {
            --stack_size;
            if (stack_t[stack_size] <= hit->t) {
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
    if (closest < 0) {
        return false;
    }
    hit->primitive = rc_as_uint(triangles[closest].v0.w);
    return true;
}

RC_FUNC Hit rc_trace_closest(RC_GLOBAL const BvhNode* nodes, RC_GLOBAL const Triangle* triangles,
                             Ray ray) {
    Hit hit;
    rc_traverse(nodes, triangles, ray, false, &hit);
    return hit;
}

RC_FUNC bool rc_trace_any(RC_GLOBAL const BvhNode* nodes, RC_GLOBAL const Triangle* triangles,
                          Ray ray) {
    Hit hit;
    return rc_traverse(nodes, triangles, ray, true, &hit);
}
