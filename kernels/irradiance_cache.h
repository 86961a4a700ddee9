// Irradiance caching's camera side (host/methods/irradiance_cache.cpp): camera samples and the
// final shading of a sample with cached diffuse indirect light.
#pragma once

#include "common/camera.h"
#include "common/irradiance_cache.h"
#include "common/path_radiance.h"

// World size of a pixel at distance t along the camera ray through pixel (x, y).
RC_FUNC float rc_ic_pixel_footprint(const CameraParams* camera, float x, float y, float t) {
    const float3 d = camera->top_left.xyz + camera->right.xyz * (x / (float)camera->resolution.x) +
                     camera->down.xyz * (y / (float)camera->resolution.y);
    return t * length(camera->right.xyz) / ((float)camera->resolution.x * length(d));
}

// The camera ray of sample s of a pixel (the same jitter in every pass that regenerates it).
RC_FUNC Ray rc_ic_camera_ray(const IcParams* params, const CameraParams* camera, uint pixel, uint s,
                             RngStream* rng, float* x, float* y) {
    *rng = rc_rng_stream(params->seed.x, params->seed.y, pixel, s);
    *x = (float)(pixel % (uint)params->image.x) + rc_rng_next_float(rng);
    *y = (float)(pixel / (uint)params->image.x) + rc_rng_next_float(rng);
    return rc_camera_ray(camera, *x, *y);
}

// The records as the shading pass reads them.
typedef struct RecordCache {
    RecordGrid grid;
    RC_GLOBAL const int* cell_start;
    RC_GLOBAL const int* cell_records;
    RC_GLOBAL const IrradianceRecord* records;
} RecordCache;

typedef struct CachedShading {
    float3 radiance;  // direct + indirect
    float3 direct;    // emission, next-event estimation and BRDF-sampled emission (MIS)
    float3 indirect;  // diffuse from the cache + glossy by path tracing
    float3 albedo;
    float3 normal;
    float coverage;  // sum of record weights
    float3 marks;    // record centres (red) and influence borders (green)
    uint rays;
} CachedShading;

// Record centres and influence borders near p, for the `records` AOV.
RC_FUNC float3 rc_ic_record_marks(const RecordCache* cache, float accuracy, float3 p,
                                  float footprint) {
    const int cell = rc_ic_grid_cell(&cache->grid, p);
    float3 marks = (float3)(0.0f);
    if (cell < 0) {
        return marks;
    }
    for (int i = cache->cell_start[cell]; i < cache->cell_start[cell + 1]; ++i) {
        RC_GLOBAL const IrradianceRecord* record = cache->records + cache->cell_records[i];
        const float d = length(p - record->position.xyz);
        const float influence = accuracy * record->position.w;
        if (d < fmax(0.08f * influence, 1.5f * footprint)) {
            marks.x = 1.0f;
        } else if (fabs(d - influence) < footprint) {
            marks.y = 1.0f;
        }
    }
    return marks;
}

// Sample s of a pixel: emission and direct light as the path tracer's first vertex computes
// them, indirect light of the diffuse lobe from the cache (rho_d / pi E), indirect light of the
// specular lobe (phong, ward) by a path sampled from that lobe.
RC_FUNC CachedShading rc_ic_shade(const SceneData* scene, const CameraParams* camera,
                                  const IcParams* params, const RecordCache* cache, uint pixel,
                                  uint s) {
    CachedShading c;
    c.radiance = c.direct = c.indirect = c.albedo = c.normal = c.marks = (float3)(0.0f);
    c.coverage = 0.0f;
    c.rays = 1;
    RngStream rng;
    float x, y;
    const Ray ray = rc_ic_camera_ray(params, camera, pixel, s, &rng, &x, &y);
    const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
    if (hit.primitive == RC_NO_HIT) {
        if (scene->environment >= 0) {
            c.direct = scene->lights[scene->environment].radiance.xyz;
        }
        c.radiance = c.direct;
        return c;
    }
    const SurfacePoint sp = rc_surface_point(scene, ray, hit);
    const SurfaceMaterial material = rc_surface_material(scene, &sp);
    c.albedo = material.diffuse + material.specular;
    c.normal = sp.shading.n;
    const float3 wo = rc_to_local(&sp.shading, -ray.direction.xyz);
    if (sp.light >= 0 && sp.front) {
        c.direct += scene->lights[sp.light].radiance.xyz;
    }
    c.direct += rc_next_event(scene, &sp, &material, wo, &rng, &c.rays);
    c.direct += rc_bsdf_sampled_emission(scene, &sp, &material, wo, &rng, &c.rays);
    if (rc_luminance(material.diffuse) > 0.0f) {
        const float4 gathered =
            rc_ic_gather(&cache->grid, cache->cell_start, cache->cell_records, cache->records,
                         sp.position, sp.shading.n, params->weights.x, params->weights.y);
        c.coverage = gathered.w;
        if (gathered.w > 0.0f) {
            c.indirect += material.diffuse * RC_INV_PI * (gathered.xyz / gathered.w);
        }
    }
    if (material.kind != RC_MATERIAL_DIFFUSE && !rc_is_black(material.specular)) {
        SurfaceMaterial lobe = material;
        lobe.diffuse = (float3)(0.0f);
        lobe.diffuse_probability = 0.0f;
        const float u_lobe = rc_rng_next_float(&rng);
        const float u1 = rc_rng_next_float(&rng);
        const float u2 = rc_rng_next_float(&rng);
        float3 wi;
        float pdf;
        float3 f;
        if (rc_material_sample(&lobe, wo, u_lobe, u1, u2, &wi, &pdf, &f)) {
            const float3 direction = rc_from_local(&sp.shading, wi);
            if (dot(direction, sp.geometric_normal) > 0.0f) {
                Ray next;
                next.origin = (float4)(sp.origin, 0.0f);
                next.direction = (float4)(direction, INFINITY);
                const PathSample p =
                    rc_path_radiance(scene, next, &rng, 1, params->depth.x, params->depth.y, false);
                c.rays += p.rays;
                c.indirect += f * (wi.z / pdf) * p.radiance;
            }
        }
    }
    c.marks = rc_ic_record_marks(cache, params->weights.x, sp.position,
                                 rc_ic_pixel_footprint(camera, x, y, hit.t));
    c.radiance = c.direct + c.indirect;
    return c;
}
