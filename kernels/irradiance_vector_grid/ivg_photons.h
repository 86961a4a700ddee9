// Photon tracing of the irradiance vector grid (host/methods/irradiance_vector_grid/
// irradiance_vector_grid.cpp): photons emitted by the lights and traced into the grid.
#pragma once

#include "common/path_radiance.h"
#include "common/sampling.h"
#include "irradiance_vector_grid/ivg_deposit.h"

// Photon streams are keyed apart from the camera's and the records' streams.
#define RC_IVG_PHOTON_DOMAIN 0x9e3779b9u

typedef struct Photon {
    Ray ray;       // unit direction
    float3 power;  // flux carried, before the division by the photon count
    bool alive;
} Photon;

// Emits a photon: a light chosen by power (the scene's light cdf), then a position and direction
// distributed as the light's emission, power = the light's flux / selection probability.
// Area lights: a triangle by area, a uniform point, a cosine-distributed direction about the
// winding normal (flux pi L A). Point lights: uniform directions (4 pi I). Spot lights: uniform
// directions in the cutoff cone, weighted by the falloff (I 2 pi (1 - cos cutoff) falloff). The
// constant environment: a uniform direction, a uniform point on the disk of the scene's bounding
// sphere perpendicular to it, entering from outside (L pi R^2 4 pi).
RC_FUNC Photon rc_ivg_emit(const SceneData* scene, const IvgParams* p, RngStream* rng) {
    const float u_light = rc_rng_next_float(rng);
    const float u1 = rc_rng_next_float(rng);
    const float u2 = rc_rng_next_float(rng);
    const float u3 = rc_rng_next_float(rng);
    const float u4 = rc_rng_next_float(rng);
    Photon photon;
    photon.alive = false;
    photon.power = (float3)(0.0f);
    photon.ray.origin = (float4)(0.0f);
    photon.ray.direction = (float4)(0.0f, 0.0f, 1.0f, INFINITY);
    if (scene->light_count <= 0) {
        return photon;
    }
    const int l = rc_sample_cdf(scene->light_cdf, scene->light_count, u_light);
    const float selection = rc_cdf_probability(scene->light_cdf, l);
    if (!(selection > 0.0f)) {
        return photon;
    }
    const Light light = scene->lights[l];
    const int kind = light.kind;
    float3 origin;
    float3 direction;
    if (kind == RC_LIGHT_AREA) {
        const int first = light.first_triangle;
        const int entry =
            first + rc_sample_cdf(scene->light_triangle_cdf + first, light.triangle_count, u1);
        RC_GLOBAL const Triangle* triangle =
            scene->triangles + scene->triangle_of_primitive[scene->light_triangles[entry]];
        // Uniform point on the triangle (pbrt-v3 §13.6.5), cosine direction about the normal.
        const float su = sqrt(u2);
        const float b0 = 1.0f - su;
        const float b1 = u3 * su;
        const float3 nl = rc_triangle_normal(triangle);
        origin = rc_offset_ray_origin(rc_hit_point(triangle, b1, 1.0f - b0 - b1), nl, triangle);
        direction = rc_to_world(rc_cosine_hemisphere(u4, rc_rng_next_float(rng)), nl);
        photon.power = light.radiance.xyz * (RC_PI * light.area);
    } else if (kind == RC_LIGHT_POINT) {
        origin = light.position.xyz;
        direction = rc_direction_about((float3)(0.0f, 0.0f, 1.0f), 1.0f - 2.0f * u1, u2);
        photon.power = light.radiance.xyz * (4.0f * RC_PI);
    } else if (kind == RC_LIGHT_SPOT) {
        origin = light.position.xyz;
        const float cos_cutoff = light.cos_cutoff;
        direction = rc_direction_about(light.axis.xyz, 1.0f - u1 * (1.0f - cos_cutoff), u2);
        photon.power = light.radiance.xyz *
                       (2.0f * RC_PI * (1.0f - cos_cutoff) * rc_spot_falloff(&light, direction));
    } else if (kind == RC_LIGHT_DISTANT) {
        // Uniform on the disk of the scene's bounding sphere facing the light, upstream of the
        // scene, along the light (pbrt-v4 §12.4, DistantLight::SampleLe): power E pi r^2.
        const float radius = p->sphere_radius;
        direction = light.axis.xyz;
        const float2 disk = rc_concentric_disk(u3, u4);
        float3 t;
        float3 b;
        rc_orthonormal_basis(direction, &t, &b);
        origin = p->sphere_centre.xyz + radius * (disk.x * t + disk.y * b - direction);
        photon.power = light.radiance.xyz * (RC_PI * radius * radius);
    } else {
        // The environment: a direction towards it, uniform or by its map's distribution
        // (density pdf), the photon travelling back along it from the scene's disk facing it:
        // power L / pdf x pi r^2 (4 pi^2 r^2 L for a uniform L).
        const float radius = p->sphere_radius;
        float3 radiance = light.radiance.xyz;
        float pdf = RC_INV_FOUR_PI;
        if (light.map < 0) {
            direction = rc_direction_about((float3)(0.0f, 0.0f, 1.0f), 1.0f - 2.0f * u1, u2);
        } else {
            direction = -rc_sample_environment(scene, &light, u1, u2, &pdf, &radiance);
        }
        const float2 disk = rc_concentric_disk(u3, u4);
        float3 t;
        float3 b;
        rc_orthonormal_basis(direction, &t, &b);
        origin = p->sphere_centre.xyz + radius * (disk.x * t + disk.y * b - direction);
        if (light.map < 0) {
            photon.power = radiance * (4.0f * RC_PI * RC_PI * radius * radius);
        } else {
            photon.power = pdf > 0.0f ? radiance * (RC_PI * radius * radius / pdf) : (float3)(0.0f);
        }
    }
    photon.power /= selection;
    photon.ray.origin = (float4)(origin, 0.0f);
    photon.ray.direction = (float4)(direction, INFINITY);
    photon.alive = !rc_is_black(photon.power);
    return photon;
}

// Traces photon `index` (its own random stream) and deposits its segments into accum: every
// segment after the first bounce, and the first too when p->include_direct (direct light). A photon
// reflects by BRDF sampling with Russian roulette from the Russian-roulette depth (survival
// probability the largest channel of f cos / pdf, at most 1), for at most max depth - 1 bounces
// (the camera path's bounce at the surface that reads the grid is the last). Counts the rays in
// *rays; returns the crossings deposited.
RC_FUNC uint rc_ivg_trace_photon(const SceneData* scene, const IvgParams* p, uint index,
                                 RC_GLOBAL volatile long* accum, uint* rays) {
    RngStream rng = rc_rng_stream(p->seed_lo ^ RC_IVG_PHOTON_DOMAIN, p->seed_hi, index, 0);
    Photon photon = rc_ivg_emit(scene, p, &rng);
    uint crossings = 0;
    if (!photon.alive) {
        return 0;
    }
    const int max_depth = p->max_depth;
    const int rr_depth = p->rr_depth;
    for (int bounces = 0;; ++bounces) {
        const Ray ray = photon.ray;
        const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
        ++*rays;
        const float far = length(ray.origin.xyz - p->sphere_centre.xyz) + 2.0f * p->sphere_radius;
        const float3 end =
            ray.origin.xyz + ray.direction.xyz * (hit.primitive == RC_NO_HIT ? far : hit.t);
        if (bounces > 0 || p->include_direct != 0) {
            crossings += rc_ivg_deposit_segment(p, ray.origin.xyz, end, photon.power, accum);
        }
        if (hit.primitive == RC_NO_HIT || bounces + 2 > max_depth) {
            break;
        }
        const SurfacePoint sp = rc_surface_point(scene, ray, hit);
        const SurfaceMaterial material = rc_surface_material(scene, &sp);
        const float3 wo = rc_to_local(&sp.shading, -ray.direction.xyz);
        BsdfSample b;
        float3 direction;
        float3 origin;
        if (!rc_sample_bounce(&sp, &material, wo, &rng, &b, &direction, &origin)) {
            break;
        }
        const float u_survive = rc_rng_next_float(&rng);
        // Photons carry flux, not radiance: undo the 1 / eta'^2 of a refraction.
        float3 factor = rc_bounce_weight(&b) * (b.eta * b.eta);
        if (bounces + 1 >= rr_depth) {
            const float survive = fmin(1.0f, rc_max_component(factor));
            if (!(u_survive < survive)) {
                break;
            }
            factor /= survive;
        }
        photon.power *= factor;
        photon.ray.origin = (float4)(origin, 0.0f);
        photon.ray.direction = (float4)(direction, INFINITY);
    }
    return crossings;
}
