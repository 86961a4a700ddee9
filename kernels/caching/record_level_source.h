// A deeper cache level of irradiance records as a radiance source (records/radiance_source.h,
// RC_RADIANCE_RECORDS; --ic-bounces): at a ray's hit, direct light by next-event estimation, the
// diffuse lobe's indirect light interpolated from the level's records, the other lobes (and the
// diffuse lobe where no record covers the hit) by path tracing (rc_ic_cached_radiance).
#pragma once

#include "caching/pipeline_shading.h"

typedef RecordCache RadianceSource;

// As host/methods/caching/record_level_source.h binds them.
#define RC_RADIANCE_SOURCE_PARAMETERS                                                   \
    RecordGrid level_grid, RC_GLOBAL const int *level_cell_start,                       \
        RC_GLOBAL const int *level_cell_records, RC_GLOBAL const Record *level_records, \
        RC_GLOBAL const IrradiancePayload *level_payloads, float level_accuracy,        \
        float level_max_weight,
#define RC_RADIANCE_SOURCE_DATA()                                                        \
    {                                                                                    \
        level_grid, level_cell_start, level_cell_records, level_records, level_payloads, \
            level_accuracy, level_max_weight                                             \
    }

RC_FUNC SourceSample rc_source_radiance(const SceneData *scene, const RadianceSource *source,
                                        Ray ray, RngStream *rng, bool count_emission, int bounces,
                                        int max_depth, int rr_depth) {
    const CachedRadiance c = rc_ic_cached_radiance(scene, source, 0, 0, 0, ray, rng, count_emission,
                                                   1, bounces, max_depth, rr_depth);
    const SourceSample r = {c.direct + c.indirect, c.distance, c.rays};
    return r;
}
