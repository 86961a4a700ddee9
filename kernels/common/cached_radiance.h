// The light a ray brings back from its first hit when the diffuse indirect light there comes from
// a cache (irradiance records, the irradiance vector grid): the parts every caching method shares.
// The method reads its cache between rc_cached_vertex and rc_trace_lobes.
#pragma once

#include "common/path_radiance.h"

typedef struct CachedRadiance {
    float3 direct;    // emission (when counted), next-event estimation and BRDF-sampled emission
    float3 indirect;  // diffuse from the cache + the other lobes by path tracing
    float3 albedo;
    float3 normal;
    float3 position;
    float coverage;  // the cache's own measure of how well it covers the hit (IC: sum of weights)
    bool served;     // the cache was read (a diffuse lobe and bounces left for indirect light)
    float distance;  // to the hit; infinite for a miss
    uint rays;
} CachedRadiance;

// The material less its diffuse lobe: what is left to path tracing (or to next-event
// estimation) where a cache provides the diffuse lobe's light.
RC_FUNC SurfaceMaterial rc_without_diffuse(const SurfaceMaterial* material) {
    SurfaceMaterial m = *material;
    m.diffuse = (float3)(0.0f);
    m.diffuse_probability = 0.0f;
    return m;
}

// The material less its specular lobe: its diffuse lobe alone (where a cache provides the
// specular lobe's indirect light).
RC_FUNC SurfaceMaterial rc_without_specular(const SurfaceMaterial* material) {
    SurfaceMaterial m = *material;
    m.kind = RC_MATERIAL_DIFFUSE;
    m.specular = (float3)(0.0f);
    m.diffuse_probability = 1.0f;
    return m;
}

// c with no light, no hit and `rays` rays.
RC_FUNC void rc_cached_radiance_clear(CachedRadiance* c, uint rays) {
    c->direct = c->indirect = c->albedo = c->normal = c->position = (float3)(0.0f);
    c->coverage = 0.0f;
    c->served = false;
    c->distance = INFINITY;
    c->rays = rays;
}

// rc_cached_vertex at a hit of `ray` already found (hit.primitive a primitive's): fills c (whose
// light starts at 0) as rc_cached_vertex does, adding the rays its light samples trace.
RC_FUNC bool rc_cached_vertex_at(const SceneData* scene, Ray ray, Hit hit, RngStream* rng,
                                 bool count_emission, bool diffuse_direct, int light_samples,
                                 int bounces, int max_depth, CachedRadiance* c, SurfacePoint* sp,
                                 SurfaceMaterial* material, float3* wo) {
    *sp = rc_surface_point(scene, ray, hit);
    *material = rc_surface_material(scene, sp);
    c->albedo = material->diffuse + material->specular;
    c->normal = sp->shading.n;
    c->position = sp->position;
    c->distance = hit.t;
    *wo = rc_to_local(&sp->shading, -ray.direction.xyz);
    if (sp->light >= 0 && sp->front && count_emission) {
        c->direct += scene->lights[sp->light].radiance.xyz;
    }
    if (bounces >= max_depth) {
        return false;  // the path may bounce no more
    }
    const SurfaceMaterial lit = diffuse_direct ? *material : rc_without_diffuse(material);
    c->direct += rc_next_event(scene, sp, &lit, *wo, light_samples, rng, &c->rays);
    c->direct += rc_bsdf_sampled_emission(scene, sp, &lit, *wo, light_samples, rng, &c->rays);
    return true;
}

// Traces `ray` and fills c with its hit (albedo, normal, position, distance), the hit's emission
// (if count_emission) and its direct light as the path tracer's vertex computes them: of every
// lobe, or, when !diffuse_direct (a cache provides the diffuse lobe's direct light too), of the
// other lobes only, with `light_samples` light samples beside the one BRDF sample (the render
// pass's camera hits take --light-samples, other vertices 1). `bounces`: the bounces the ray's
// path made before (for the depth limit).
// Returns true at a hit that may still reflect light (bounces < max_depth), with the hit in *sp,
// *material and *wo (the direction back along the ray, in the shading frame); indirect light
// there takes one bounce more (bounces + 1 < max_depth).
RC_FUNC bool rc_cached_vertex(const SceneData* scene, Ray ray, RngStream* rng, bool count_emission,
                              bool diffuse_direct, int light_samples, int bounces, int max_depth,
                              CachedRadiance* c, SurfacePoint* sp, SurfaceMaterial* material,
                              float3* wo) {
    rc_cached_radiance_clear(c, 1);
    const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
    if (hit.primitive == RC_NO_HIT) {
        if (scene->environment >= 0 && count_emission) {
            c->direct = rc_environment_light(scene, ray.direction.xyz);
        }
        return false;
    }
    return rc_cached_vertex_at(scene, ray, hit, rng, count_emission, diffuse_direct, light_samples,
                               bounces, max_depth, c, sp, material, wo);
}

// The indirect light of the lobes of `traced` (the material less what the cache served) at sp, by
// one path sampled from those lobes, added to c->indirect.
RC_FUNC void rc_trace_lobes(const SceneData* scene, const SurfacePoint* sp,
                            const SurfaceMaterial* traced, float3 wo, RngStream* rng, int bounces,
                            int max_depth, int rr_depth, CachedRadiance* c) {
    if (rc_is_black(traced->diffuse) &&
        (traced->kind == RC_MATERIAL_DIFFUSE || rc_is_black(traced->specular)) &&
        (traced->kind != RC_MATERIAL_DIFFUSE_TRANSMISSION || rc_is_black(traced->k))) {
        return;
    }
    BsdfSample b;
    float3 direction;
    float3 origin;
    if (rc_sample_bounce(sp, traced, wo, rng, &b, &direction, &origin)) {
        Ray next;
        next.origin = (float4)(origin, 0.0f);
        next.direction = (float4)(direction, INFINITY);
        const PathSample p =
            rc_path_radiance(scene, next, rng, bounces + 1, max_depth, rr_depth, false);
        c->rays += p.rays;
        c->indirect += rc_bounce_weight(&b) * p.radiance;
    }
}
