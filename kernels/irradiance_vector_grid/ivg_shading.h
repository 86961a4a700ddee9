// The grid's render pass (host/methods/irradiance_vector_grid/ivg_method.cpp): camera samples
// shaded with the grid read at their hits (`ivg`) or at the hits of gather rays (`ivg-gather`).
#pragma once

#include "common/camera.h"
#include "common/camera_film.h"
#include "common/ivg_radiance.h"
#include "common/pixel_sampler.h"
#include "common/sampling.h"

// The camera ray of sample s of a pixel's pass, and its random stream: camera sample
// p->first_sample + s.
RC_FUNC Ray rc_ivg_camera_ray(const IvgParams* p, const CameraParams* camera, uint pixel, uint s,
                              RngStream* rng) {
    const float2 position = rc_camera_sample_position(camera, p->seed_lo, p->seed_hi, pixel,
                                                      (uint)p->first_sample + s, rng);
    return rc_camera_ray(camera, position.x, position.y);
}

// Camera sample s of a pixel with final gathering (params.gather_rays gather rays): exact direct
// light at the camera's hit (params.light_samples light samples); its diffuse lobe's indirect light
// from cosine-distributed, stratified gather rays whose hits give direct light plus the grid's
// diffuse light; the other lobes by path tracing. *grid_term: the grid read at the camera's hit
// (the `grid` layer).
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
    if (!rc_cached_vertex(scene, ray, &rng, true, true, grid->params.light_samples, 0, max_depth,
                          &c, &sp, &material, &wo) ||
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
                rc_direction_about((float3)(0.0f, 0.0f, 1.0f), sqrt(fmax(0.0f, 1.0f - u1)), u2);
            const float3 direction = rc_from_local(&sp.shading, shading_direction);
            if (dot(direction, sp.geometric_normal) <= 0.0f) {
                continue;
            }
            Ray gather;
            gather.origin = (float4)(sp.origin, 0.0f);
            gather.direction = (float4)(direction, INFINITY);
            float3 unused;
            const CachedRadiance l =
                rc_ivg_radiance(scene, grid, gather, &rng, false, 1, 1, &unused);
            c.rays += l.rays;
            sum += l.direct + l.indirect;
        }
        // Cosine sampling: f cos / pdf = rho_d per ray.
        c.indirect += material.diffuse * sum / (float)gathers;
    }
    rc_trace_lobes(scene, &sp, &traced, wo, &rng, 0, max_depth, grid->params.rr_depth, &c);
    return c;
}

// What the render pass's camera samples read (rc_shade_pixel).
struct PixelShader {
    const SceneData* scene;
    const VectorGrid* grid;
    const CameraParams* camera;
};

// Camera sample s of a pixel: with params.gather_rays gather rays, final gathering
// (`ivg-gather`); with none, the grid read directly at the camera's hit (`ivg`); direct light at
// the camera's hit with params.light_samples light samples. Its layer is the grid's diffuse light
// at the camera's hit.
RC_FUNC FilmSample rc_shade_camera_sample(const PixelShader* shader, uint pixel, uint s) {
    FilmSample c;
    c.glossy = (float3)(0.0f);
    c.order = 0.0f;
    c.hits = 0.0f;
    if (shader->grid->params.gather_rays > 0) {
        c.light = rc_ivg_gather(shader->scene, shader->grid, shader->camera, pixel, s, &c.layer);
    } else {
        RngStream rng;
        const Ray ray = rc_ivg_camera_ray(&shader->grid->params, shader->camera, pixel, s, &rng);
        c.light = rc_ivg_radiance(shader->scene, shader->grid, ray, &rng, true,
                                  shader->grid->params.light_samples, 0, &c.layer);
    }
    return c;
}
