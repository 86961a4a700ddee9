// One path sample of the reference path tracer (DESIGN.md §6.1): unidirectional, next-event
// estimation at every vertex combined with BRDF sampling by multiple importance sampling (power
// heuristic; Veach 1997, ch. 9), Russian roulette from a given depth, a maximum depth.
// Depth counts bounces: emission seen directly is depth 0, direct lighting depth 1.
#pragma once

#include "common/bvh_traversal.h"
#include "common/camera.h"
#include "common/light.h"
#include "common/material.h"
#include "common/math.h"
#include "common/ray_offset.h"
#include "common/scene_data.h"
#include "shared/rng.h"
#include "shared/types.h"

typedef struct PathSample {
    float3 radiance;  // beauty = direct + indirect
    float3 direct;    // paths of at most one bounce
    float3 indirect;  // paths of two bounces or more
    float3 albedo;    // first hit: diffuse + specular reflectance
    float3 normal;    // first hit: shading normal, facing the camera
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

RC_FUNC PathSample rc_path_sample(const SceneData* scene, const CameraParams* camera,
                                  const PathTracerParams* params, uint pixel) {
    PathSample s;
    s.direct = s.indirect = s.albedo = s.normal = (float3)(0.0f);
    s.rays = 0;
    RngStream rng = rc_rng_stream(params->seed.x, params->seed.y, pixel, (uint)params->image.z);
    const uint px = pixel % (uint)params->image.x;
    const uint py = pixel / (uint)params->image.x;
    const float jx = rc_rng_next_float(&rng);
    const float jy = rc_rng_next_float(&rng);
    Ray ray = rc_camera_ray(camera, (float)px + jx, (float)py + jy);

    float3 throughput = (float3)(1.0f);
    float previous_pdf = 0.0f;  // BRDF pdf of the last bounce (for MIS on emitters hit)
    float3 previous_position = ray.origin.xyz;
    const int max_depth = params->depth.x;
    for (int depth = 0;; ++depth) {
        const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
        s.rays += 1;
        if (hit.primitive == RC_NO_HIT) {
            if (scene->environment >= 0) {
                const float weight =
                    depth == 0 ? 1.0f : rc_power_heuristic(previous_pdf, rc_environment_pdf(scene));
                rc_add_contribution(
                    &s, depth,
                    throughput * scene->lights[scene->environment].radiance.xyz * weight);
            }
            break;
        }
        const SurfacePoint sp = rc_surface_point(scene, ray, hit);
        const SurfaceMaterial material = rc_surface_material(scene, &sp);
        if (depth == 0) {
            s.albedo = material.diffuse + material.specular;
            s.normal = sp.shading.n;
        }
        // Emission reached by BRDF sampling (or seen directly).
        if (sp.light >= 0 && sp.front) {
            const float weight =
                depth == 0 ? 1.0f
                           : rc_power_heuristic(
                                 previous_pdf, rc_area_light_pdf(scene, sp.light, previous_position,
                                                                 sp.position, sp.geometric_normal));
            rc_add_contribution(&s, depth,
                                throughput * scene->lights[sp.light].radiance.xyz * weight);
        }
        if (depth >= max_depth) {
            break;
        }
        const float3 wo = rc_to_local(&sp.shading, -ray.direction.xyz);
        const float3 origin = sp.origin;

        // Next-event estimation: one light, chosen by power.
        if (scene->light_count > 0) {
            const float u_light = rc_rng_next_float(&rng);
            const float u1 = rc_rng_next_float(&rng);
            const float u2 = rc_rng_next_float(&rng);
            const float u3 = rc_rng_next_float(&rng);
            const int l = rc_sample_cdf(scene->light_cdf, scene->light_count, u_light);
            const LightSample ls = rc_sample_light(
                scene, l, rc_cdf_probability(scene->light_cdf, l), sp.position, u1, u2, u3);
            if (ls.pdf > 0.0f && !rc_is_black(ls.radiance) &&
                dot(ls.direction, sp.geometric_normal) > 0.0f) {
                const float3 wi = rc_to_local(&sp.shading, ls.direction);
                const float3 f = rc_material_eval(&material, wo, wi);
                if (!rc_is_black(f)) {
                    s.rays += 1;
                    if (!rc_occluded(scene, origin, ls.target, ls.infinite, ls.direction)) {
                        const float weight =
                            ls.delta
                                ? 1.0f
                                : rc_power_heuristic(ls.pdf, rc_material_pdf(&material, wo, wi));
                        rc_add_contribution(
                            &s, depth + 1, throughput * f * (wi.z * weight / ls.pdf) * ls.radiance);
                    }
                }
            }
        }

        // Continue the path by sampling the BRDF.
        const float u_lobe = rc_rng_next_float(&rng);
        const float u1 = rc_rng_next_float(&rng);
        const float u2 = rc_rng_next_float(&rng);
        float3 wi;
        float pdf;
        float3 f;
        if (!rc_material_sample(&material, wo, u_lobe, u1, u2, &wi, &pdf, &f)) {
            break;
        }
        const float3 direction = rc_from_local(&sp.shading, wi);
        if (dot(direction, sp.geometric_normal) <= 0.0f) {
            break;  // below the geometric surface: shading normals must not leak light
        }
        throughput *= f * (wi.z / pdf);
        previous_pdf = pdf;
        previous_position = sp.position;
        if (depth + 1 >= params->depth.y) {
            const float survive = fmin(rc_max_component(throughput), 0.95f);
            if (rc_rng_next_float(&rng) >= survive) {
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
