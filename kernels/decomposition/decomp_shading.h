// The decomposition's camera side (the paper, §6 "The Whole Algorithm", pass 2): camera samples,
// the two terms of eq. 3 at each one, and the render pass that shades them: direct light by
// next-event estimation, the diffuse lobe's indirect light rho_d / pi (I_D + I_N) (eq. 3), the
// other lobes by path tracing.
#pragma once

#include "caching/pipeline_shading.h"
#include "common/cached_radiance.h"
#include "common/camera.h"
#include "common/pixel_sampler.h"
#include "decomposition/decomp_far.h"
#include "decomposition/decomp_near.h"

// The camera ray of sample s of a pixel's pass (the G-buffer and the render pass draw the same
// one): camera sample params->first_sample + s.
RC_FUNC Ray rc_decomp_camera_ray(const DecompParams* params, const CameraParams* camera, uint pixel,
                                 uint s, RngStream* rng, float* x, float* y) {
    const float2 position = rc_camera_sample_position(camera, params->seed_lo, params->seed_hi,
                                                      pixel, (uint)params->first_sample + s, rng);
    *x = position.x;
    *y = position.y;
    return rc_camera_ray(camera, *x, *y);
}

// The first hit of camera sample s of a pixel: where the far field is sampled and the two terms
// are evaluated. served: it has a diffuse lobe and indirect light (max_depth >= 2). footprint:
// the world size of a pixel there.
RC_FUNC GBufferSample rc_decomp_gbuffer_sample(const DecompParams* params, const SceneData* scene,
                                               const CameraParams* camera, uint pixel, uint s) {
    RngStream rng;
    float x, y;
    const Ray ray = rc_decomp_camera_ray(params, camera, pixel, s, &rng, &x, &y);
    GBufferSample g = rc_ic_gbuffer_sample(scene, ray);
    if (g.primitive >= 0) {
        g.footprint = rc_ic_pixel_footprint(camera, x, y, g.footprint);
    }
    g.served = g.served != 0 && params->max_depth >= 2 ? 1 : 0;
    return g;
}

// The far-field samples as the kernels read them: a record grid over their reach (the shared
// record layout: position = the cluster's centre, radius = its reach), their coefficients and
// their gradients (null without --decomp-gradients on).
typedef struct FarField {
    RecordGrid grid;
    RC_GLOBAL const int* cell_start;
    RC_GLOBAL const int* cell_samples;
    RC_GLOBAL const Record* samples;
    RC_GLOBAL const ShSample* coefficients;
    RC_GLOBAL const ShGradient* gradients;
} FarField;

// I_D and I_N at a G-buffer entry (eq. 3 and 4): the far-field samples interpolated at its point,
// I_D their irradiance about its normal, I_N the near correction read against them. Zero where
// the entry is not served.
RC_FUNC DecompIrradiance rc_decomp_irradiance(const FarField* far, const NearField* near,
                                              const GBufferSample* g) {
    DecompIrradiance e;
    e.far = e.near = (float4)(0.0f);
    e.near_count = e.far_samples = e.near_rays = 0;
    e.pad0 = 0;
    if (g->served == 0) {
        return e;
    }
    const float3 p = g->position.xyz;
    const float3 n = g->normal.xyz;
    ShSample radiance;
    const int cell = rc_ic_grid_cell(&far->grid, p);
    const int begin = cell < 0 ? 0 : far->cell_start[cell];
    const int end = cell < 0 ? 0 : far->cell_start[cell + 1];
    const FarCoefficients coefficients = {far->coefficients, far->gradients};
    e.far_samples = rc_decomp_interpolate(far->cell_samples, begin, end, far->samples,
                                          &coefficients, p, n, &radiance);
    e.far = (float4)(rc_decomp_sh_irradiance(&radiance, n), 0.0f);
    uint count = 0;
    uint rays = 0;
    e.near =
        (float4)(rc_decomp_near_correction(near, &radiance, p, g->origin.xyz, n, &count, &rays),
                 0.0f);
    e.near_count = count;
    e.near_rays = rays;
    return e;
}

// What one camera sample gives the film: its light (the diffuse lobe's indirect light from the
// decomposition) and that light's diffuse part rho_d / pi max(0, I_D + I_N) and its two terms,
// rho_d / pi I_D and rho_d / pi I_N.
typedef struct DecompSample {
    CachedRadiance light;
    float3 diffuse;
    float3 far;
    float3 near;
} DecompSample;

// The diffuse lobe's indirect light at a camera hit of reflectance rho_d from its entry of the
// evaluation buffer (eq. 3: B = rho / pi (I_D + I_N); negative where the near correction
// overshoots, clamped), into out's parts.
RC_FUNC void rc_decomp_diffuse_indirect(float3 diffuse, const DecompIrradiance* e,
                                        DecompSample* out) {
    const float3 reflectance = diffuse * RC_INV_PI;
    out->far = reflectance * e->far.xyz;
    out->near = reflectance * e->near.xyz;
    out->diffuse = reflectance * fmax(e->far.xyz + e->near.xyz, (float3)(0.0f));
}

// Camera sample s of a pixel: emission and direct light at its hit (params->light_samples light
// samples), the diffuse lobe's indirect light from the evaluation buffer, the other lobes by a
// path sampled from them.
RC_FUNC DecompSample rc_decomp_shade_sample(const DecompParams* params, const SceneData* scene,
                                            const CameraParams* camera,
                                            RC_GLOBAL const DecompIrradiance* irradiance,
                                            uint pixel, uint s) {
    DecompSample out;
    out.diffuse = out.far = out.near = (float3)(0.0f);
    RngStream rng;
    float x, y;
    const Ray ray = rc_decomp_camera_ray(params, camera, pixel, s, &rng, &x, &y);
    SurfacePoint sp;
    SurfaceMaterial material;
    float3 wo;
    if (!rc_cached_vertex(scene, ray, &rng, true, true, params->light_samples, 0, params->max_depth,
                          &out.light, &sp, &material, &wo) ||
        1 >= params->max_depth) {
        return out;
    }
    SurfaceMaterial traced = rc_without_diffuse(&material);
    if (rc_luminance(material.diffuse) > 0.0f) {
        const DecompIrradiance e = irradiance[(size_t)pixel * (uint)params->camera_spp + s];
        rc_decomp_diffuse_indirect(material.diffuse, &e, &out);
        out.light.indirect += out.diffuse;
        out.light.served = true;
    }
    rc_trace_lobes(scene, &sp, &traced, wo, &rng, 0, params->max_depth, params->rr_depth,
                   &out.light);
    return out;
}

// Camera sample s of a pixel past the fully shaded ones (--decomp-indirect-spp): only the diffuse
// lobe's indirect light and its two terms (out.diffuse, out.far, out.near), for the camera ray's
// one ray (out.light.rays; its light left 0).
RC_FUNC DecompSample rc_decomp_indirect_sample(const DecompParams* params, const SceneData* scene,
                                               const CameraParams* camera,
                                               RC_GLOBAL const DecompIrradiance* irradiance,
                                               uint pixel, uint s) {
    DecompSample out;
    out.diffuse = out.far = out.near = (float3)(0.0f);
    rc_cached_radiance_clear(&out.light, 1);
    RngStream rng;
    float x, y;
    const Ray ray = rc_decomp_camera_ray(params, camera, pixel, s, &rng, &x, &y);
    const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
    if (hit.primitive == RC_NO_HIT || 1 >= params->max_depth) {
        return out;
    }
    const SurfacePoint sp = rc_surface_point(scene, ray, hit);
    const SurfaceMaterial material = rc_surface_material(scene, &sp);
    if (rc_luminance(material.diffuse) > 0.0f) {
        const DecompIrradiance e = irradiance[(size_t)pixel * (uint)params->camera_spp + s];
        rc_decomp_diffuse_indirect(material.diffuse, &e, &out);
    }
    return out;
}

// The diffuse lobe's indirect light and its two terms summed over a pixel's camera samples past
// the fully shaded ones (--decomp-indirect-spp), with the count of finite ones.
typedef struct DecompDiffuseSums {
    float3 diffuse;
    float3 far;
    float3 near;
    uint finite;
} DecompDiffuseSums;

// Adds the diffuse sums of a pixel's camera samples params->shaded_spp .. camera_spp - 1 to *sums
// (counters as rc_decomp_shade_pixel's); the rays they traced.
RC_FUNC uint rc_decomp_indirect_samples(const DecompParams* params, const SceneData* scene,
                                        const CameraParams* camera,
                                        RC_GLOBAL const DecompIrradiance* irradiance, uint pixel,
                                        DecompDiffuseSums* sums, RC_GLOBAL uint* counters) {
    uint rays = 0;
    for (uint s = (uint)params->shaded_spp; s < (uint)params->camera_spp; ++s) {
        const DecompSample c =
            rc_decomp_indirect_sample(params, scene, camera, irradiance, pixel, s);
        rays += c.light.rays;
        if (!all(isfinite(c.diffuse)) || !all(isfinite(c.near)) || !all(isfinite(c.far))) {
            atomic_inc(&counters[1]);
            atomic_min(&counters[2], pixel);
            continue;
        }
        ++sums->finite;
        sums->diffuse += c.diffuse;
        sums->far += c.far;
        sums->near += c.near;
    }
    return rays;
}

// Shades a pixel's camera samples and writes the means over the finite ones to its
// RC_DECOMP_FILM_SLOTS film slots: of the first params->shaded_spp, every layer; of the others
// (--decomp-indirect-spp), the diffuse lobe's indirect light and its two terms, whose means then
// run over all the pixel's finite samples (the layers that hold that light take the mean over all
// of it, the rest over the shaded ones). counters: [0] rays traced, [1] non-finite samples
// (dropped), [2] the first pixel that had one.
RC_FUNC void rc_decomp_shade_pixel(const DecompParams* params, const SceneData* scene,
                                   const CameraParams* camera,
                                   RC_GLOBAL const DecompIrradiance* irradiance, uint pixel,
                                   RC_GLOBAL float4* film, RC_GLOBAL uint* counters) {
    float3 sums[RC_DECOMP_FILM_SLOTS];
    for (int k = 0; k < RC_DECOMP_FILM_SLOTS; ++k) {
        sums[k] = (float3)(0.0f);
    }
    DecompDiffuseSums shaded = {(float3)(0.0f), (float3)(0.0f), (float3)(0.0f), 0};
    uint rays = 0;
    for (uint s = 0; s < (uint)params->shaded_spp; ++s) {
        const DecompSample c = rc_decomp_shade_sample(params, scene, camera, irradiance, pixel, s);
        const float3 radiance = c.light.direct + c.light.indirect;
        rays += c.light.rays;
        if (!all(isfinite(radiance)) || !all(isfinite(c.near)) || !all(isfinite(c.far))) {
            atomic_inc(&counters[1]);
            atomic_min(&counters[2], pixel);
            continue;
        }
        ++shaded.finite;
        shaded.diffuse += c.diffuse;
        sums[RC_DECOMP_FILM_BEAUTY] += radiance;
        sums[RC_DECOMP_FILM_DIRECT] += c.light.direct;
        sums[RC_DECOMP_FILM_INDIRECT] += c.light.indirect;
        sums[RC_DECOMP_FILM_ALBEDO] += c.light.albedo;
        sums[RC_DECOMP_FILM_NORMAL] += c.light.normal;
        sums[RC_DECOMP_FILM_FAR] += c.far;
        sums[RC_DECOMP_FILM_NEAR] += c.near;
    }
    DecompDiffuseSums extra = {(float3)(0.0f), (float3)(0.0f), (float3)(0.0f), 0};
    rays += rc_decomp_indirect_samples(params, scene, camera, irradiance, pixel, &extra, counters);
    atomic_add(&counters[0], rays);
    const float inv = shaded.finite > 0 ? 1.0f / (float)shaded.finite : 0.0f;
    float3 means[RC_DECOMP_FILM_SLOTS];
    for (int k = 0; k < RC_DECOMP_FILM_SLOTS; ++k) {
        means[k] = sums[k] * inv;
    }
    if (params->camera_spp > params->shaded_spp) {
        // The diffuse part's mean over every finite sample in place of the shaded ones' alone.
        const uint counted = shaded.finite + extra.finite;
        const float inv_all = counted > 0 ? 1.0f / (float)counted : 0.0f;
        const float3 diffuse = (shaded.diffuse + extra.diffuse) * inv_all - shaded.diffuse * inv;
        means[RC_DECOMP_FILM_BEAUTY] += diffuse;
        means[RC_DECOMP_FILM_INDIRECT] += diffuse;
        means[RC_DECOMP_FILM_FAR] = (sums[RC_DECOMP_FILM_FAR] + extra.far) * inv_all;
        means[RC_DECOMP_FILM_NEAR] = (sums[RC_DECOMP_FILM_NEAR] + extra.near) * inv_all;
    }
    RC_GLOBAL float4* out = film + RC_DECOMP_FILM_SLOTS * (size_t)pixel;
    for (int k = 0; k < RC_DECOMP_FILM_SLOTS; ++k) {
        out[k] = (float4)(means[k], 0.0f);
    }
}
