// Irradiance caching's ray side (host/methods/irradiance_cache/): camera samples, the rays of
// a record's hemisphere, and the light a ray brings back when the diffuse indirect light at its
// hit comes from a cache level.
#pragma once

#include "caching/irradiance_records.h"
#include "common/cached_radiance.h"
#include "common/camera.h"
#include "common/camera_film.h"
#include "common/pixel_sampler.h"
#include "shared/radiance_cache.h"

// World size of a pixel at distance t along the camera ray through pixel (x, y).
RC_FUNC float rc_ic_pixel_footprint(const CameraParams* camera, float x, float y, float t) {
    const float3 d = camera->top_left.xyz + camera->right.xyz * (x / (float)camera->resolution.x) +
                     camera->down.xyz * (y / (float)camera->resolution.y);
    return t * length(camera->right.xyz) / ((float)camera->resolution.x * length(d));
}

// The G-buffer entry of a ray's first hit (irradiance caching's camera samples and hemisphere
// hits, the decomposition's camera samples), with the hit distance as its footprint (to be scaled
// by the caller: rc_ic_pixel_footprint for a camera ray). served: it has a diffuse lobe.
RC_FUNC GBufferSample rc_ic_gbuffer_sample(const SceneData* scene, Ray ray) {
    const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
    GBufferSample g;
    g.position = g.normal = g.origin = (float4)(0.0f);
    g.footprint = g.diffuse = 0.0f;
    g.primitive = -1;
    g.served = 0;
    if (hit.primitive != RC_NO_HIT) {
        const SurfacePoint sp = rc_surface_point(scene, ray, hit);
        const SurfaceMaterial material = rc_surface_material(scene, &sp);
        const float diffuse = rc_luminance(material.diffuse);
        g.position = (float4)(sp.position, 0.0f);
        g.normal = (float4)(sp.shading.n, 0.0f);
        g.origin = (float4)(sp.origin, 0.0f);
        g.footprint = hit.t;
        g.diffuse = diffuse;
        g.primitive = (int)hit.primitive;
        g.served = diffuse > 0.0f ? 1 : 0;
    }
    return g;
}

// A deeper cache level's "pixel", per unit distance: a quarter of the angular width of one of the
// M N strata of a record's hemisphere (sqrt(2 pi / (M N)) radians). Records at deeper levels are
// spaced more finely than the hemisphere rays that read them: spacing them by whole strata left
// visible bias on the Cornell box (docs/irradiance-caching.md).
RC_FUNC float rc_ic_deeper_pixel_width(const IcParams* params) {
    return 0.25f * sqrt(2.0f * RC_PI / (float)(params->strata_m * params->strata_n));
}

// The camera ray of sample s of a pixel (the same jitter in every pass that regenerates it): the
// pixel's sample params->first_sample + s (a later pass of a render by time).
RC_FUNC Ray rc_ic_camera_ray(const IcParams* params, const CameraParams* camera, uint pixel, uint s,
                             RngStream* rng, float* x, float* y) {
    const float2 position = rc_camera_sample_position(camera, params->seed_lo, params->seed_hi,
                                                      pixel, (uint)params->first_sample + s, rng);
    *x = position.x;
    *y = position.y;
    return rc_camera_ray(camera, *x, *y);
}

// The ray through cell `cell` (row j = cell / N, column k = cell % N) of record `record` (its
// random stream; params->level its level), leaving `origin` about normal n; *rng continues
// the cell's stream after the jitter.
RC_FUNC Ray rc_ic_cell_ray(const IcParams* params, uint record, uint cell, float3 n, float3 origin,
                           RngStream* rng) {
    *rng = rc_ic_cell_stream(params, record, cell);
    const float zeta = rc_rng_next_float(rng);
    const float xi = rc_rng_next_float(rng);
    const int j = (int)cell / params->strata_n;
    const int k = (int)cell % params->strata_n;
    const Frame frame = rc_ic_record_frame(n);
    Ray ray;
    ray.origin = (float4)(origin, 0.0f);
    ray.direction =
        (float4)(rc_from_local(&frame, rc_ic_cell_direction(j, k, params->strata_m,
                                                            params->strata_n, zeta, xi)),
                 INFINITY);
    return ray;
}

// One cache level as the kernels read it, and how its records are weighted.
typedef struct RecordCache {
    RecordGrid grid;
    RC_GLOBAL const int* cell_start;
    RC_GLOBAL const int* cell_records;
    RC_GLOBAL const Record* records;
    RC_GLOBAL const IrradiancePayload* payloads;  // entry i: records[i]'s
    float accuracy;
    float max_weight;
} RecordCache;

// The indirect light of the specular lobe at a camera sample that radiance caching serves
// (glossy->order >= 0): Material.specular times the records' interpolated reflection
// (RcGlossySample) where its order is positive and a record covers the sample, else by a path
// sampled from the specular lobe (the Monte Carlo fallback, TVCG 2005 §4.1).
RC_FUNC float3 rc_ic_glossy_light(const SceneData* scene, const SurfacePoint* sp,
                                  const SurfaceMaterial* material, float3 wo,
                                  RC_GLOBAL const RcGlossySample* glossy, RngStream* rng,
                                  int bounces, int max_depth, int rr_depth, uint* rays) {
    if (glossy->order > 0 && glossy->weight > 0.0f) {
        return material->specular * (glossy->reflected.xyz / glossy->weight);
    }
    CachedRadiance traced;
    traced.indirect = (float3)(0.0f);
    traced.rays = 0;
    const SurfaceMaterial specular = rc_without_diffuse(material);
    rc_trace_lobes(scene, sp, &specular, wo, rng, bounces, max_depth, rr_depth, &traced);
    *rays += traced.rays;
    return traced.indirect;
}

// Light arriving along `ray`: at its hit, emission (if count_emission) and direct light as the
// path tracer's vertex computes them, indirect light of the diffuse lobe from the cache
// (rho_d / pi E, Ward et al. 1988), indirect light of the specular lobe (phong, ward) by a path
// sampled from that lobe. Where no record covers the hit, the diffuse lobe is path traced too.
// `bounces`: the bounces the ray's path made before (for the depth limit). `splat`: the hit's
// entry of the splat buffer (sum w E', sum w) for a camera sample, or 0: gathered from the cache.
// `glossy`: a camera sample's entry of radiance caching's glossy buffer, or 0; where it serves
// the specular lobe (order >= 0) that lobe's indirect light comes from rc_ic_glossy_light and is
// also written to *glossy_light. `light_samples`: next-event estimation's light samples at the
// hit (rc_cached_vertex).
RC_FUNC CachedRadiance rc_ic_cached_radiance(const SceneData* scene, const RecordCache* cache,
                                             RC_GLOBAL const float4* splat,
                                             RC_GLOBAL const RcGlossySample* glossy,
                                             float3* glossy_light, Ray ray, RngStream* rng,
                                             bool count_emission, int light_samples, int bounces,
                                             int max_depth, int rr_depth) {
    CachedRadiance c;
    SurfacePoint sp;
    SurfaceMaterial material;
    float3 wo;
    if (!rc_cached_vertex(scene, ray, rng, count_emission, true, light_samples, bounces, max_depth,
                          &c, &sp, &material, &wo) ||
        bounces + 1 >= max_depth) {
        return c;
    }
    SurfaceMaterial traced = rc_without_diffuse(&material);  // the lobes left to path tracing
    if (rc_luminance(material.diffuse) > 0.0f) {
        const float4 gathered =
            splat != 0 ? *splat
                       : rc_ic_gather(&cache->grid, cache->cell_start, cache->cell_records,
                                      cache->records, cache->payloads, sp.position, sp.shading.n,
                                      cache->accuracy, cache->max_weight);
        c.coverage = gathered.w;
        c.served = true;
        if (gathered.w > 0.0f) {
            c.indirect += material.diffuse * RC_INV_PI * (gathered.xyz / gathered.w);
        } else {
            traced = material;
        }
    }
    if (glossy != 0 && glossy->order >= 0) {
        const float3 light = rc_ic_glossy_light(scene, &sp, &material, wo, glossy, rng, bounces,
                                                max_depth, rr_depth, &c.rays);
        c.indirect += light;
        *glossy_light = light;
        traced = rc_without_specular(&traced);
    }
    rc_trace_lobes(scene, &sp, &traced, wo, rng, bounces, max_depth, rr_depth, &c);
    return c;
}

// Record centres and influence borders near p, for the `records` AOV.
RC_FUNC float3 rc_ic_record_marks(const RecordCache* cache, float accuracy, float3 p,
                                  float footprint) {
    const int cell = rc_ic_grid_cell(&cache->grid, p);
    float3 marks = (float3)(0.0f);
    if (cell < 0) {
        return marks;
    }
    for (int i = cache->cell_start[cell]; i < cache->cell_start[cell + 1]; ++i) {
        RC_GLOBAL const Record* record = cache->records + cache->cell_records[i];
        const float d = length(p - record->position.xyz);
        const float influence = accuracy * record->radius;
        if (d < fmax(0.08f * influence, 1.5f * footprint)) {
            marks.x = 1.0f;
        } else if (fabs(d - influence) < footprint) {
            marks.y = 1.0f;
        }
    }
    return marks;
}

// What the render pass's camera samples read (rc_shade_pixel).
struct PixelShader {
    const SceneData* scene;
    const CameraParams* camera;
    const IcParams* params;
    const RecordCache* cache;       // the first cache level
    RC_GLOBAL const float4* splat;  // the splat buffer: entry pixel * spp + s per camera sample
    // Radiance caching's glossy buffer, the same entries (read when params->glossy_cache).
    RC_GLOBAL const RcGlossySample* glossy;
};

// Camera sample s of a pixel, shaded with the first cache level, its direct light with
// params->light_samples light samples (--light-samples). Its layer is the records
// overlay: record centres (red) and influence borders (green), when drawn, over the image at half
// brightness.
RC_FUNC FilmSample rc_shade_camera_sample(const PixelShader* shader, uint pixel, uint s) {
    const IcParams* params = shader->params;
    FilmSample c;
    RngStream rng;
    float x, y;
    const Ray ray = rc_ic_camera_ray(params, shader->camera, pixel, s, &rng, &x, &y);
    const size_t entry = (size_t)pixel * (uint)params->camera_spp + s;
    RC_GLOBAL const RcGlossySample* glossy = params->glossy_cache != 0 ? shader->glossy + entry : 0;
    c.glossy = (float3)(0.0f);
    c.order = glossy != 0 ? (float)max(glossy->rc_order, 0) : 0.0f;
    c.hits = glossy != 0 ? glossy->hits : 0.0f;
    c.light = rc_ic_cached_radiance(shader->scene, shader->cache, shader->splat + entry, glossy,
                                    &c.glossy, ray, &rng, true, params->light_samples, 0,
                                    params->max_depth, params->rr_depth);
    float3 marks = (float3)(0.0f);
    if (params->draw_records != 0 && isfinite(c.light.distance)) {
        marks = rc_ic_record_marks(shader->cache, params->accuracy, c.light.position,
                                   rc_ic_pixel_footprint(shader->camera, x, y, c.light.distance));
    }
    c.layer = any(marks > 0.0f) ? marks : 0.5f * (c.light.direct + c.light.indirect);
    return c;
}
