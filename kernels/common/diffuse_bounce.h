// Secondary rays leaving a hit point: the continuation of a diffuse bounce.
#pragma once

#include "common/ray_offset.h"
#include "common/sampling.h"
#include "common/triangle_geometry.h"
#include "shared/rng.h"
#include "shared/types.h"

// The hit point of a closest hit, reconstructed from the barycentrics (more accurate than
// origin + t * direction, Ray Tracing Gems ch. 6).
RC_FUNC float3 rc_hit_point(RC_GLOBAL const Triangle* triangle, float u, float v) {
    return (1.0f - u - v) * triangle->v0.xyz + u * triangle->v1.xyz + v * triangle->v2.xyz;
}

// A cosine-distributed ray from the hit of `ray`, on the side the ray came from, its origin
// offset off the surface. A ray that hit nothing gives a ray with zero direction (not traceable).
RC_FUNC Ray rc_diffuse_bounce_ray(Ray ray, Hit hit, RC_GLOBAL const Triangle* triangles,
                                  RC_GLOBAL const uint* triangle_of_primitive, RngStream* rng) {
    Ray bounce;
    bounce.origin = (float4)(0.0f);
    bounce.direction = (float4)(0.0f);
    if (hit.primitive == RC_NO_HIT) {
        return bounce;
    }
    RC_GLOBAL const Triangle* triangle = triangles + triangle_of_primitive[hit.primitive];
    float3 n = rc_triangle_normal(triangle);
    if (dot(n, ray.direction.xyz) > 0.0f) {
        n = -n;
    }
    const float3 p = rc_hit_point(triangle, hit.u, hit.v);
    const float u1 = rc_rng_next_float(rng);
    const float u2 = rc_rng_next_float(rng);
    const float3 direction = rc_to_world(rc_cosine_hemisphere(u1, u2), n);
    bounce.origin = (float4)(rc_offset_surface_origin(p, n, triangle), 0.0f);
    bounce.direction = (float4)(direction, INFINITY);
    return bounce;
}
