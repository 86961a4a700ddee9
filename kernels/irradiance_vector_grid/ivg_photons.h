// The irradiance vector grid's ray side (host/methods/irradiance_vector_grid.cpp,
// host/methods/ivg_method.cpp): photons emitted by the lights and traced into the grid, and the
// light a ray brings back when the diffuse indirect light at its hit is read from the grid.
#pragma once

#include "common/cached_radiance.h"
#include "common/camera.h"
#include "common/sampling.h"
#include "irradiance_vector_grid/ivg_lookup.h"

// Photon streams are keyed apart from the camera's and the records' streams.
#define RC_IVG_PHOTON_DOMAIN 0x9e3779b9u

// The grid as the kernels read it.
typedef struct VectorGrid {
    IvgParams params;
    RC_GLOBAL const float* values;
    RC_GLOBAL const half* packed;
} VectorGrid;

typedef struct Photon {
    Ray ray;       // unit direction
    float3 power;  // flux carried, before the division by the photon count
    bool alive;
} Photon;

// A unit direction about axis `n` at polar cosine cos_theta and azimuth 2 pi u.
RC_FUNC float3 rc_ivg_direction_about(float3 n, float cos_theta, float u) {
    const float sin_theta = sqrt(fmax(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * RC_PI * u;
    return rc_to_world((float3)(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta), n);
}

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
    const int kind = light.info.x;
    float3 origin;
    float3 direction;
    if (kind == RC_LIGHT_AREA) {
        const int first = light.info.y;
        const int entry =
            first + rc_sample_cdf(scene->light_triangle_cdf + first, light.info.z, u1);
        RC_GLOBAL const Triangle* triangle =
            scene->triangles + scene->triangle_of_primitive[scene->light_triangles[entry]];
        // Uniform point on the triangle (pbrt-v3 §13.6.5), cosine direction about the normal.
        const float su = sqrt(u2);
        const float b0 = 1.0f - su;
        const float b1 = u3 * su;
        const float3 nl = rc_triangle_normal(triangle);
        origin = rc_offset_ray_origin(rc_hit_point(triangle, b1, 1.0f - b0 - b1), nl);
        direction = rc_to_world(rc_cosine_hemisphere(u4, rc_rng_next_float(rng)), nl);
        photon.power = light.radiance.xyz * (RC_PI * light.shape.x);
    } else if (kind == RC_LIGHT_POINT) {
        origin = light.position.xyz;
        direction = rc_ivg_direction_about((float3)(0.0f, 0.0f, 1.0f), 1.0f - 2.0f * u1, u2);
        photon.power = light.radiance.xyz * (4.0f * RC_PI);
    } else if (kind == RC_LIGHT_SPOT) {
        origin = light.position.xyz;
        const float cos_cutoff = light.axis.w;
        direction = rc_ivg_direction_about(light.axis.xyz, 1.0f - u1 * (1.0f - cos_cutoff), u2);
        photon.power = light.radiance.xyz *
                       (2.0f * RC_PI * (1.0f - cos_cutoff) * rc_spot_falloff(&light, direction));
    } else {
        const float radius = p->sphere_radius;
        direction = rc_ivg_direction_about((float3)(0.0f, 0.0f, 1.0f), 1.0f - 2.0f * u1, u2);
        const float2 disk = rc_concentric_disk(u3, u4);
        float3 t;
        float3 b;
        rc_orthonormal_basis(direction, &t, &b);
        origin = p->sphere_centre.xyz + radius * (disk.x * t + disk.y * b - direction);
        photon.power = light.radiance.xyz * (4.0f * RC_PI * RC_PI * radius * radius);
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
        float3 wi;
        float pdf;
        float3 f;
        float3 direction;
        if (!rc_sample_bounce(&sp, &material, wo, &rng, &wi, &pdf, &f, &direction)) {
            break;
        }
        const float u_survive = rc_rng_next_float(&rng);
        float3 factor = f * (wi.z / pdf);
        if (bounces + 1 >= rr_depth) {
            const float survive = fmin(1.0f, rc_max_component(factor));
            if (!(u_survive < survive)) {
                break;
            }
            factor /= survive;
        }
        photon.power *= factor;
        photon.ray.origin = (float4)(sp.origin, 0.0f);
        photon.ray.direction = (float4)(direction, INFINITY);
    }
    return crossings;
}

// The diffuse light the grid gives a surface point: rho_d / pi E (§3.2, eq. 1), interpolated
// over the corners of its cell the point sees (a shadow ray from the point's ray origin to just
// short of each corner; counted in *rays): corners behind a wall hold the other side's light.
RC_FUNC float3 rc_ivg_diffuse(const SceneData* scene, const VectorGrid* grid,
                              const SurfaceMaterial* material, const SurfacePoint* sp, uint* rays) {
    const IvgParams* p = &grid->params;
    const int3 base = rc_ivg_cell_base(p, rc_ivg_grid_coordinates(p, sp->position));
    int visible = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const float3 vertex = rc_ivg_corner_position(p, base, corner);
        const float3 target = vertex + 0.01f * (sp->origin - vertex);
        if (!rc_occluded(scene, sp->origin, target, false, target - sp->origin)) {
            visible |= 1 << corner;
        }
    }
    *rays += 8;
    return material->diffuse * RC_INV_PI *
           rc_ivg_irradiance(p, grid->values, grid->packed, sp->position, sp->shading.n, visible);
}

// Light arriving along `ray` when the grid provides the diffuse lobe's indirect light at its hit
// (and its direct light too when the grid holds direct light, params.include_direct): emission (if
// count_emission), next-event estimation, rho_d / pi E from the grid, and the other lobes by a
// path sampled from them. *grid_term: the grid's part. `bounces`: the bounces the ray's path made
// before.
RC_FUNC CachedRadiance rc_ivg_radiance(const SceneData* scene, const VectorGrid* grid, Ray ray,
                                       RngStream* rng, bool count_emission, int bounces,
                                       float3* grid_term) {
    CachedRadiance c;
    SurfacePoint sp;
    SurfaceMaterial material;
    float3 wo;
    const int max_depth = grid->params.max_depth;
    const bool direct_in_grid = grid->params.include_direct != 0;
    *grid_term = (float3)(0.0f);
    if (!rc_cached_vertex(scene, ray, rng, count_emission, !direct_in_grid, bounces, max_depth, &c,
                          &sp, &material, &wo)) {
        return c;
    }
    const bool indirect = bounces + 1 < max_depth;
    if (rc_luminance(material.diffuse) > 0.0f && (indirect || direct_in_grid)) {
        *grid_term = rc_ivg_diffuse(scene, grid, &material, &sp, &c.rays);
        c.indirect += *grid_term;
        c.served = true;
    }
    if (indirect) {
        const SurfaceMaterial traced = rc_without_diffuse(&material);
        rc_trace_lobes(scene, &sp, &traced, wo, rng, bounces, max_depth, grid->params.rr_depth, &c);
    }
    return c;
}

// The camera ray of sample s of a pixel, and its random stream.
RC_FUNC Ray rc_ivg_camera_ray(const IvgParams* p, const CameraParams* camera, uint pixel, uint s,
                              RngStream* rng) {
    *rng = rc_rng_stream(p->seed_lo, p->seed_hi, pixel, s);
    const float x = (float)(pixel % (uint)camera->resolution.x) + rc_rng_next_float(rng);
    const float y = (float)(pixel / (uint)camera->resolution.x) + rc_rng_next_float(rng);
    return rc_camera_ray(camera, x, y);
}

// Camera sample s of a pixel with final gathering (params.gather_rays gather rays): exact direct
// light at the camera's hit; its diffuse lobe's indirect light from cosine-distributed, stratified
// gather rays whose hits give direct light plus the grid's diffuse light; the
// other lobes by path tracing. *grid_term: the grid read at the camera's hit (the `grid` layer).
RC_FUNC CachedRadiance rc_ivg_gather(const SceneData* scene, const VectorGrid* grid,
                                     const CameraParams* camera, uint pixel, uint s,
                                     float3* grid_term) {
    RngStream rng;
    const Ray ray = rc_ivg_camera_ray(&grid->params, camera, pixel, s, &rng);
    CachedRadiance c;
    SurfacePoint sp;
    SurfaceMaterial material;
    float3 wo;
    const int max_depth = grid->params.max_depth;
    *grid_term = (float3)(0.0f);
    if (!rc_cached_vertex(scene, ray, &rng, true, true, 0, max_depth, &c, &sp, &material, &wo) ||
        1 >= max_depth) {
        return c;
    }
    SurfaceMaterial traced = rc_without_diffuse(&material);
    if (rc_luminance(material.diffuse) > 0.0f) {
        *grid_term = rc_ivg_diffuse(scene, grid, &material, &sp, &c.rays);
        c.served = true;
        // Gather rays stratified over m x n cells of the cosine-weighted hemisphere (cos^2 theta
        // = 1 - u1, phi = 2 pi u2), m the largest divisor of their count up to its square root.
        const int gathers = max(grid->params.gather_rays, 1);
        int m = (int)(sqrt((float)gathers) + 0.5f);
        while (m * m > gathers || gathers % m != 0) {
            --m;
        }
        const int n = gathers / m;
        float3 sum = (float3)(0.0f);
        for (int g = 0; g < gathers; ++g) {
            const float u1 = ((float)(g / n) + rc_rng_next_float(&rng)) / (float)m;
            const float u2 = ((float)(g % n) + rc_rng_next_float(&rng)) / (float)n;
            const float3 shading_direction =
                rc_ivg_direction_about((float3)(0.0f, 0.0f, 1.0f), sqrt(fmax(0.0f, 1.0f - u1)), u2);
            const float3 direction = rc_from_local(&sp.shading, shading_direction);
            if (dot(direction, sp.geometric_normal) <= 0.0f) {
                continue;
            }
            Ray gather;
            gather.origin = (float4)(sp.origin, 0.0f);
            gather.direction = (float4)(direction, INFINITY);
            float3 unused;
            const CachedRadiance l = rc_ivg_radiance(scene, grid, gather, &rng, false, 1, &unused);
            c.rays += l.rays;
            sum += l.direct + l.indirect;
        }
        // Cosine sampling: f cos / pdf = rho_d per ray.
        c.indirect += material.diffuse * sum / (float)gathers;
    }
    rc_trace_lobes(scene, &sp, &traced, wo, &rng, 0, max_depth, grid->params.rr_depth, &c);
    return c;
}
