// The light a ray brings back when the diffuse indirect light at its hit is read from the
// irradiance vector grid: what the grid's render pass and the grid as a radiance source
// (ivg_source.h) share. Lookup only: no deposition (64-bit atomics) here.
#pragma once

#include "common/cached_radiance.h"
#include "common/ivg_lookup.h"
#include "common/ivg_visibility.h"

// The grid as the kernels read it.
typedef struct VectorGrid {
    IvgParams params;
    RC_GLOBAL const float* values;
    RC_GLOBAL const half* packed;
    RC_GLOBAL const IvgCellPlanes* cell_planes;  // per cell, into planes (ivg_visibility.h)
    RC_GLOBAL const IvgPlane* planes;
} VectorGrid;

// The diffuse light the grid gives a surface point: rho_d / pi E (§3.2, eq. 1), interpolated
// over the corners of its cell the point sees (rc_ivg_visible_corners: a shadow ray from the
// point's ray origin to just short of each corner its cell's planes do not prove unblocked;
// counted in *rays): corners behind a wall hold the other side's light.
RC_FUNC float3 rc_ivg_diffuse(const SceneData* scene, const VectorGrid* grid,
                              const SurfaceMaterial* material, const SurfacePoint* sp, uint* rays) {
    const IvgParams* p = &grid->params;
    const int visible = rc_ivg_visible_corners(scene, p, grid->cell_planes, grid->planes, sp, rays);
    return material->diffuse * RC_INV_PI *
           rc_ivg_irradiance(p, grid->values, grid->packed, sp->position, sp->shading.n, visible);
}

// Light arriving along `ray` when the grid provides the diffuse lobe's indirect light at its hit
// (and its direct light too when the grid holds direct light, params.include_direct): emission (if
// count_emission), next-event estimation, rho_d / pi E from the grid, and the other lobes by a
// path sampled from them. *grid_term: the grid's part. `light_samples`: next-event estimation's
// light samples at the hit (rc_cached_vertex). `bounces`: the bounces the ray's path made before.
RC_FUNC CachedRadiance rc_ivg_radiance(const SceneData* scene, const VectorGrid* grid, Ray ray,
                                       RngStream* rng, bool count_emission, int light_samples,
                                       int bounces, float3* grid_term) {
    CachedRadiance c;
    SurfacePoint sp;
    SurfaceMaterial material;
    float3 wo;
    const int max_depth = grid->params.max_depth;
    const bool direct_in_grid = grid->params.include_direct != 0;
    *grid_term = (float3)(0.0f);
    if (!rc_cached_vertex(scene, ray, rng, count_emission, !direct_in_grid, light_samples, bounces,
                          max_depth, &c, &sp, &material, &wo)) {
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
