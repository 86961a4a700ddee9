// The irradiance vector grid as a radiance source (records/radiance_source.h,
// RC_RADIANCE_GRID; --ic-ivg): at a ray's hit, direct light by next-event estimation (unless the
// grid holds it), rho_d / pi E from the grid, the other lobes by path tracing (rc_ivg_radiance,
// with the grid's own depth limits).
#pragma once

#include "common/ivg_radiance.h"

typedef VectorGrid RadianceSource;

// As host/methods/grid/irradiance_vector_grid.h binds them (not formatted:
// clang-format reads the macro's pointers as the file's style and would flip the functions').
// clang-format off
#define RC_RADIANCE_SOURCE_PARAMETERS                                                             \
    IvgParams grid_params, RC_GLOBAL const float* grid_values, RC_GLOBAL const half* grid_packed, \
        RC_GLOBAL const IvgCellPlanes* grid_cell_planes, RC_GLOBAL const IvgPlane* grid_planes,
// clang-format on
#define RC_RADIANCE_SOURCE_DATA() \
    { grid_params, grid_values, grid_packed, grid_cell_planes, grid_planes }

RC_FUNC SourceSample rc_source_radiance(const SceneData* scene, const RadianceSource* source,
                                        Ray ray, RngStream* rng, bool count_emission, int bounces,
                                        int max_depth, int rr_depth) {
    float3 grid_term;
    const CachedRadiance c =
        rc_ivg_radiance(scene, source, ray, rng, count_emission, 1, bounces, &grid_term);
    const SourceSample r = {c.direct + c.indirect, c.distance, c.rays};
    return r;
}
