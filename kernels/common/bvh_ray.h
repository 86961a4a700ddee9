// What both BVH layouts' traversals share: which rays are traced, the per-ray set-up of the box
// test, and the leaf's triangle tests with the order-independent choice of the closest hit.
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

// Everything a traversal needs of its ray.
typedef struct TraversalRay {
    BoxRay box;
    WatertightRay watertight;
    float tmin;
    float tmax;  // the ray's own; the closest hit so far is in Hit.t
} TraversalRay;

RC_FUNC TraversalRay rc_traversal_ray(Ray ray) {
    TraversalRay r;
    r.box = rc_box_ray(ray.origin.xyz, ray.direction.xyz);
    r.watertight = rc_watertight_ray(ray.origin.xyz, ray.direction.xyz);
    r.tmin = ray.origin.w;
    r.tmax = ray.direction.w;
    return r;
}

// A hit nearer than the closest so far, or as near with a smaller primitive index: the closest
// hit is then the same whatever order the triangles are tested in (so the same in both BVH
// layouts).
RC_FUNC bool rc_is_nearer_hit(float t, uint primitive, const Hit* hit) {
    return t < hit->t || (t == hit->t && primitive < hit->primitive);
}

// Tests the `count` triangles from `first` against the ray's own interval and keeps the nearest
// in *hit; returns whether one was kept. With any_hit set, returns at the first hit.
RC_FUNC bool rc_intersect_leaf(RC_GLOBAL const Triangle* triangles, uint first, uint count,
                               const TraversalRay* r, bool any_hit, Hit* hit) {
    bool found = false;
    for (uint i = first; i < first + count; ++i) {
        const float4 v0 = triangles[i].v0;
        float t, u, v;
        if (!rc_intersect_triangle(&r->watertight, v0, triangles[i].v1, triangles[i].v2, r->tmin,
                                   r->tmax, &t, &u, &v)) {
            continue;
        }
        const uint primitive = rc_as_uint(v0.w);
        if (any_hit || rc_is_nearer_hit(t, primitive, hit)) {
            hit->t = t;
            hit->u = u;
            hit->v = v;
            hit->primitive = primitive;
            found = true;
            if (any_hit) {
                break;
            }
        }
    }
    return found;
}

// Whether a stack entry whose box the ray enters at t_enter may still hold a hit as near as the
// closest so far (the same slack as the box test's far distance).
RC_FUNC bool rc_may_hold_nearer_hit(float t_enter, const Hit* hit) {
    return t_enter <= hit->t * RC_BOX_FAR_SCALE;
}
