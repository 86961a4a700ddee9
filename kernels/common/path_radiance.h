// The path-tracing estimator shared by the reference path tracer and the caching methods:
// unidirectional paths with next-event estimation at every vertex, combined with BRDF sampling
// by multiple importance sampling (power heuristic; Veach 1997, ch. 9), Russian roulette from a
// given depth, and a maximum depth. Depth counts bounces along the path: the surface a path's
// first ray hits is depth 0, so its emission is a 0-bounce path and light it reflects from a
// light source a 1-bounce path.
#pragma once

#include "common/bvh_traversal.h"
#include "common/light.h"
#include "common/material.h"
#include "common/math.h"
#include "common/scene_data.h"
#include "shared/rng.h"
#include "shared/types.h"

typedef struct PathSample {
    float3 radiance;  // direct + indirect
    float3 direct;    // paths of at most one bounce
    float3 indirect;  // paths of two bounces or more
    float3 albedo;    // first hit: diffuse + specular reflectance
    float3 normal;    // first hit: shading normal, facing the ray
    float distance;   // first hit's distance along the (unit) ray direction; INFINITY on a miss
    uint rays;        // rays traced (closest and shadow)
} PathSample;

// Adds `value` to the direct or the indirect part by the number of bounces of its path.
RC_FUNC void rc_add_contribution(PathSample* s, int bounces, float3 value) {
    if (bounces <= 1) {
        s->direct += value;
    } else {
        s->indirect += value;
    }
}

RC_FUNC bool rc_occluded(const SceneData* scene, float3 from, float3 to, bool infinite,
                         float3 direction) {
    Ray shadow;
    shadow.origin = (float4)(from, 0.0f);
    shadow.direction = infinite ? (float4)(direction, INFINITY) : (float4)(to - from, 1.0f);
    return rc_trace_any(scene->nodes, scene->triangles, shadow);
}

// One light sample of next-event estimation at a surface point: a light chosen by power, its
// sample weighted by the power heuristic against the BRDF's density (delta lights: weight 1).
// `light_samples` is n_light of Veach's multi-sample model (1997, §9.2.2) with one BRDF sample
// beside it: the power heuristic with sample counts (§9.2.4), w = (n_light p_light)^2 /
// ((n_light p_light)^2 + p_brdf^2). Returns the sample's weighted reflected radiance towards wo
// (local frame), f cos w / p_light L, before the 1 / n_light of the multi-sample estimator;
// counts the shadow ray in *rays.
RC_FUNC float3 rc_light_sample(const SceneData* scene, const SurfacePoint* sp,
                               const SurfaceMaterial* material, float3 wo, int light_samples,
                               RngStream* rng, uint* rays) {
    const float u_light = rc_rng_next_float(rng);
    const float u1 = rc_rng_next_float(rng);
    const float u2 = rc_rng_next_float(rng);
    const float u3 = rc_rng_next_float(rng);
    if (scene->light_count <= 0) {
        return (float3)(0.0f);
    }
    const int l = rc_sample_cdf(scene->light_cdf, scene->light_count, u_light);
    const LightSample ls = rc_sample_light(scene, l, rc_cdf_probability(scene->light_cdf, l),
                                           sp->position, u1, u2, u3);
    const float side = dot(ls.direction, sp->geometric_normal);
    const bool through = rc_material_transmits(material);
    if (ls.pdf <= 0.0f || rc_is_black(ls.radiance) || side == 0.0f || (side < 0.0f && !through)) {
        return (float3)(0.0f);
    }
    const float3 wi = rc_to_local(&sp->shading, ls.direction);
    if (through && (wi.z > 0.0f) != (side > 0.0f)) {
        return (float3)(0.0f);  // the shading normal disagrees with the geometry's side
    }
    const float3 f = rc_material_eval(material, wo, wi);
    if (rc_is_black(f)) {
        return (float3)(0.0f);
    }
    *rays += 1;
    const float3 origin = side > 0.0f ? sp->origin : sp->through_origin;
    if (rc_occluded(scene, origin, ls.target, ls.infinite, ls.direction)) {
        return (float3)(0.0f);
    }
    const float weight = ls.delta ? 1.0f
                                  : rc_power_heuristic((float)light_samples * ls.pdf,
                                                       rc_material_pdf(material, wo, wi));
    return f * (fabs(wi.z) * weight / ls.pdf) * ls.radiance;
}

// Next-event estimation at a surface point with `light_samples` independent light samples
// (rc_light_sample), their mean: with rc_bsdf_sampled_emission given the same count, the
// multi-sample estimator of the point's direct light (Veach 1997, §9.2.2: F = sum over
// strategies of 1 / n_i sum_j w_i f / p_i), unbiased for every count.
RC_FUNC float3 rc_next_event(const SceneData* scene, const SurfacePoint* sp,
                             const SurfaceMaterial* material, float3 wo, int light_samples,
                             RngStream* rng, uint* rays) {
    float3 sum = (float3)(0.0f);
    if (rc_material_is_delta(material)) {
        return sum;  // no light sample can reach a delta lobe
    }
    for (int j = 0; j < light_samples; ++j) {
        sum += rc_light_sample(scene, sp, material, wo, light_samples, rng, rays);
    }
    return sum / (float)light_samples;
}

// A bounce sampled from `material` at sp with three numbers of rng (*s, in the shading frame),
// its world direction and the origin of the ray leaving along it (on the side it leaves to).
// False when sampling fails or the direction lies on the other side of the geometric surface than
// of the shading one (shading normals must not leak light).
RC_FUNC bool rc_sample_bounce(const SurfacePoint* sp, const SurfaceMaterial* material, float3 wo,
                              RngStream* rng, BsdfSample* s, float3* direction, float3* origin) {
    const float u_lobe = rc_rng_next_float(rng);
    const float u1 = rc_rng_next_float(rng);
    const float u2 = rc_rng_next_float(rng);
    if (!rc_material_sample(material, wo, u_lobe, u1, u2, s)) {
        return false;
    }
    *direction = rc_from_local(&sp->shading, s->wi);
    const float side = dot(*direction, sp->geometric_normal);
    if (s->wi.z > 0.0f) {
        *origin = sp->origin;
        return side > 0.0f;
    }
    *origin = sp->through_origin;
    return side < 0.0f;
}

// The throughput factor f |cos| / pdf of a sampled bounce.
RC_FUNC float3 rc_bounce_weight(const BsdfSample* s) { return s->f * (fabs(s->wi.z) / s->pdf); }

// The MIS weight of emission a bounce reached, against light sampling's density light_pdf (delta
// lobes: 1, light sampling cannot reach their directions).
RC_FUNC float rc_bounce_mis(const BsdfSample* s, float light_pdf) {
    return s->delta ? 1.0f : rc_power_heuristic(s->pdf, light_pdf);
}

// Emission reached by sampling the BRDF once at a surface point, weighted by the power heuristic
// against light sampling with `light_samples` light samples (their count multiplies the light
// density, Veach 1997, §9.2.4): with rc_next_event given the same count, the direct light of the
// point (what the path tracer's first bounce computes with one). Counts the ray in *rays.
RC_FUNC float3 rc_bsdf_sampled_emission(const SceneData* scene, const SurfacePoint* sp,
                                        const SurfaceMaterial* material, float3 wo,
                                        int light_samples, RngStream* rng, uint* rays) {
    BsdfSample b;
    float3 direction;
    float3 origin;
    if (!rc_sample_bounce(sp, material, wo, rng, &b, &direction, &origin)) {
        return (float3)(0.0f);
    }
    Ray ray;
    ray.origin = (float4)(origin, 0.0f);
    ray.direction = (float4)(direction, INFINITY);
    const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
    *rays += 1;
    const float3 throughput = rc_bounce_weight(&b);
    const float count = (float)light_samples;
    if (hit.primitive == RC_NO_HIT) {
        if (scene->environment < 0) {
            return (float3)(0.0f);
        }
        return throughput * rc_environment_light(scene, direction) *
               rc_bounce_mis(&b, count * rc_environment_pdf(scene, direction));
    }
    const SurfacePoint light_point = rc_surface_point(scene, ray, hit);
    if (light_point.light < 0 || !light_point.front) {
        return (float3)(0.0f);
    }
    return throughput * scene->lights[light_point.light].radiance.xyz *
           rc_bounce_mis(
               &b, count * rc_area_light_pdf(scene, light_point.light, hit.primitive, sp->position,
                                             light_point.position, light_point.geometric_normal));
}

// Radiance arriving along `ray` (unit direction), by path tracing. With first_emission false the
// emission of the surface (or environment) the ray reaches first is left out: the caller counts
// that light by its own next-event estimation. `bounces` is the number of bounces the caller's
// path already made (it shifts the direct/indirect split); paths end after max_depth bounces in
// all.
RC_FUNC PathSample rc_path_radiance(const SceneData* scene, Ray ray, RngStream* rng, int bounces,
                                    int max_depth, int rr_depth, bool first_emission) {
    PathSample s;
    s.direct = s.indirect = s.albedo = s.normal = (float3)(0.0f);
    s.distance = INFINITY;
    s.rays = 0;
    float3 throughput = (float3)(1.0f);
    BsdfSample previous;  // the last bounce (for MIS on emitters hit)
    previous.delta = true;
    previous.pdf = 0.0f;
    float3 previous_position = ray.origin.xyz;
    for (int depth = bounces;; ++depth) {
        const bool first = depth == bounces;
        const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
        s.rays += 1;
        if (hit.primitive == RC_NO_HIT) {
            if (scene->environment >= 0 && (!first || first_emission)) {
                const float3 w = ray.direction.xyz;
                const float weight =
                    first ? 1.0f : rc_bounce_mis(&previous, rc_environment_pdf(scene, w));
                rc_add_contribution(&s, depth,
                                    throughput * rc_environment_light(scene, w) * weight);
            }
            break;
        }
        const SurfacePoint sp = rc_surface_point(scene, ray, hit);
        const SurfaceMaterial material = rc_surface_material(scene, &sp);
        if (first) {
            s.albedo = material.diffuse + material.specular;
            s.normal = sp.shading.n;
            s.distance = hit.t;
        }
        // Emission reached by BRDF sampling (or seen directly).
        if (sp.light >= 0 && sp.front && (!first || first_emission)) {
            const float weight =
                first ? 1.0f
                      : rc_bounce_mis(&previous, rc_area_light_pdf(scene, sp.light, hit.primitive,
                                                                   previous_position, sp.position,
                                                                   sp.geometric_normal));
            rc_add_contribution(&s, depth,
                                throughput * scene->lights[sp.light].radiance.xyz * weight);
        }
        if (depth >= max_depth) {
            break;
        }
        const float3 wo = rc_to_local(&sp.shading, -ray.direction.xyz);
        rc_add_contribution(&s, depth + 1,
                            throughput * rc_next_event(scene, &sp, &material, wo, 1, rng, &s.rays));

        // Continue the path by sampling the BSDF.
        float3 direction;
        float3 origin;
        if (!rc_sample_bounce(&sp, &material, wo, rng, &previous, &direction, &origin)) {
            break;
        }
        throughput *= rc_bounce_weight(&previous);
        previous_position = sp.position;
        if (depth + 1 >= rr_depth) {
            const float survive = fmin(rc_max_component(throughput), 0.95f);
            if (rc_rng_next_float(rng) >= survive) {
                break;
            }
            throughput /= survive;
        }
        ray.origin = (float4)(origin, 0.0f);
        ray.direction = (float4)(direction, INFINITY);
    }
    s.radiance = s.direct + s.indirect;
    return s;
}
