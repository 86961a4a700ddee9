// Entry kernel of irradiance caching's hemisphere sampling (host/methods/irradiance_cache/): the
// radiance arriving through each cell of a batch of records, "the radiance beyond the first
// bounce" read from the source the program is built for (records/radiance_source.h).
#include "caching/pipeline_shading.h"
#include "common/kernel_range.h"
#include "scene_arguments.h"
// The source after the method's own headers (see records/radiance_source.h).
#include "caching/radiance_source.h"

// The ray of item i of a record batch: cell i % (M N) of batch record i / (M N), whose random
// stream is streams[i / (M N)].
RC_FUNC Ray rc_ic_batch_cell_ray(const IcParams* params, __global const Record* records,
                                 __global const float4* origins, __global const uint* streams,
                                 uint i, RngStream* rng) {
    const uint per_record = (uint)(params->strata_m * params->strata_n);
    const uint b = i / per_record;
    return rc_ic_cell_ray(params, streams[b], i % per_record, records[b].normal.xyz, origins[b].xyz,
                          rng);
}

// Stores a cell's (L.rgb, distance) (a NaN or infinite radiance as black) and counts its rays.
RC_FUNC void rc_ic_store_cell(__global float4* cells, __global uint* counters, uint i,
                              float3 radiance, float distance, uint rays) {
    atomic_add(&counters[0], rays);
    cells[i] = (float4)(all(isfinite(radiance)) ? radiance : (float3)(0.0f), distance);
}

// Item i: cell i % (M N) of batch record i / (M N): the radiance arriving through it and the
// distance to what it hits, as (L.rgb, distance) in cells[i]. The hemisphere ray is a bounce of
// the record's level: its hit's own emission is direct light (left to next-event estimation at
// the shading point) unless the tests ask for it. counters[0] counts the rays traced.
RC_KERNEL void ic_record_cells(uint begin, uint end, IcParams params, RC_SCENE_PARAMETERS,
                               __global const Record* records, __global const float4* origins,
                               __global const uint* streams,
                               RC_RADIANCE_SOURCE_PARAMETERS __global float4* cells,
                               __global uint* counters) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const RadianceSource source = RC_RADIANCE_SOURCE_DATA();
    RngStream rng;
    const Ray ray = rc_ic_batch_cell_ray(&params, records, origins, streams, i, &rng);
    const SourceSample s =
        rc_source_radiance(&scene, &source, ray, &rng, params.count_emission != 0, params.level + 1,
                           params.max_depth, params.rr_depth);
    rc_ic_store_cell(cells, counters, i, s.radiance, s.distance, s.rays);
}
