// Entry kernels of irradiance caching (host/methods/caching/cache_pipeline.cpp): the
// G-buffer, the hemisphere hits a deeper level must cover, the reduction of a record's hemisphere
// samples (the sampling itself: ic_record_cells.cl), record gathering (coverage and
// interpolation), and the final shading pass.
#include "caching/pipeline_shading.h"
#include "common/kernel_range.h"
#include "irradiance_cache/ic_splat.h"
#include "scene_arguments.h"

// Entry i = pixel * spp + s: the first hit of that camera sample.
RC_KERNEL void ic_gbuffer(uint begin, uint end, IcParams params, CameraParams camera,
                          RC_SCENE_PARAMETERS, __global GBufferSample* gbuffer) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint spp = (uint)params.camera_spp;
    const uint pixel = i / spp;
    RngStream rng;
    float x, y;
    const Ray ray = rc_ic_camera_ray(&params, &camera, pixel, i % spp, &rng, &x, &y);
    GBufferSample g = rc_ic_gbuffer_sample(&scene, ray);
    g.footprint = rc_ic_pixel_footprint(&camera, x, y, g.footprint);
    gbuffer[i] = g;
}

// Item i: cell i % (M N) of batch record i / (M N) (random stream streams[i / (M N)]): the first
// hit of its ray, where the next cache level must cover it (footprint: rc_ic_deeper_pixel_width
// at the hit distance).
RC_KERNEL void ic_record_hits(uint begin, uint end, IcParams params, RC_SCENE_PARAMETERS,
                              __global const Record* records, __global const float4* origins,
                              __global const uint* streams, __global GBufferSample* hits) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint per_record = (uint)(params.strata_m * params.strata_n);
    const uint b = i / per_record;
    const uint cell = i % per_record;
    RngStream rng;
    const Ray ray =
        rc_ic_cell_ray(&params, streams[b], cell, records[b].normal.xyz, origins[b].xyz, &rng);
    GBufferSample g = rc_ic_gbuffer_sample(&scene, ray);
    g.footprint *= rc_ic_deeper_pixel_width(&params);
    hits[i] = g;
}

// Item b: irradiance and gradients (into payloads[b]) and (harmonic mean, minimum) hit distance
// (into distances[b]) of batch record b (random stream streams[b]).
RC_KERNEL void ic_record_reduce(uint begin, uint end, IcParams params, __global const float4* cells,
                                __global const Record* records, __global const uint* streams,
                                __global IrradiancePayload* payloads, __global float4* distances) {
    RC_RANGE_ITEM(b);
    const uint per_record = (uint)(params.strata_m * params.strata_n);
    const RecordEstimate e =
        rc_ic_reduce(&params, streams[b], records[b].normal.xyz, cells + (size_t)b * per_record);
    __global IrradiancePayload* r = payloads + b;
    r->irradiance = (float4)(e.irradiance, 0.0f);
    r->rotation_r = (float4)(e.rotation[0], 0.0f);
    r->rotation_g = (float4)(e.rotation[1], 0.0f);
    r->rotation_b = (float4)(e.rotation[2], 0.0f);
    r->translation_r = (float4)(e.translation[0], 0.0f);
    r->translation_g = (float4)(e.translation[1], 0.0f);
    r->translation_b = (float4)(e.translation[2], 0.0f);
    r->occluder = (float4)(e.occluder, 0.0f);
    distances[b] = (float4)(e.harmonic_distance, e.min_distance, 0.0f, 0.0f);
}

// Item t: screen tile t (RC_SPLAT_TILE_SIZE pixels a side, tiles.tiles_x a row) of the camera's
// image: the nearest and farthest distance from the eye of the camera samples in it the cache
// serves, (+inf, -inf) when there is none. A record's influence sphere reaches no sample of a
// tile whose depths it does not overlap: the host leaves it out of that tile's list.
RC_KERNEL void ic_tile_depths(uint begin, uint end, IcParams params, CameraParams camera,
                              SplatTileGrid tiles, __global const GBufferSample* gbuffer,
                              __global TileDepths* depths) {
    RC_RANGE_ITEM(t);
    depths[t] = rc_ic_tile_depths(&params, &camera, &tiles, gbuffer, t);
}

// Item q: candidate q of a placement pass (rc_ic_candidate), G-buffer entry i: appends i to
// uncovered[] when the cache serves it but no record of its list covers it (the test stops at
// the first covering record); count[0] counts them (the host sorts them). The lists are either
// the screen tiles records were splatted into (tiles.tile_size > 0: camera samples; their splat
// buffer entry would have no weight, course "Radiance Cache Splatting", Algorithm 2 step 4) or
// the world-space grid's cells (a deeper level's hemisphere hits, gathered).
RC_KERNEL void ic_uncovered(uint begin, uint end, IcParams params, SplatTileGrid tiles,
                            RecordGrid grid, __global const int* list_start,
                            __global const int* list_records, __global const Record* records,
                            __global const IrradiancePayload* payloads,
                            __global const GBufferSample* gbuffer, __global uint* uncovered,
                            __global uint* count) {
    RC_RANGE_ITEM(q);
    const uint i = rc_ic_candidate(&params, q);
    const GBufferSample g = gbuffer[i];
    if (g.served == 0) {
        return;
    }
    const int list = tiles.tile_size > 0 ? (int)rc_ic_sample_tile(&params, &tiles, i)
                                         : rc_ic_grid_cell(&grid, g.position.xyz);
    if (list < 0 ||
        !rc_ic_any_weight(list_records, list_start[list], list_start[list + 1], records, payloads,
                          g.position.xyz, g.normal.xyz, params.accuracy, params.max_weight)) {
        uncovered[atomic_inc(&count[0])] = i;
    }
}

// Item k: G-buffer entry indices[k], copied to out[k].
RC_KERNEL void ic_gbuffer_select(uint begin, uint end, __global const GBufferSample* gbuffer,
                                 __global const uint* indices, __global GBufferSample* out) {
    RC_RANGE_ITEM(k);
    out[k] = gbuffer[indices[k]];
}

// Item q: the gather at candidate q (rc_ic_candidate), G-buffer entry i: (sum w E', sum w) of
// the records the world-space grid lists at its point, into sums[q]. For points that are not
// camera samples (a deeper cache level's hemisphere hits); 0 where the cache does not serve i.
RC_KERNEL void ic_gather(uint begin, uint end, IcParams params, RecordGrid grid,
                         __global const int* cell_start, __global const int* cell_records,
                         __global const Record* records, __global const IrradiancePayload* payloads,
                         __global const GBufferSample* gbuffer, __global float4* sums) {
    RC_RANGE_ITEM(q);
    const GBufferSample g = gbuffer[rc_ic_candidate(&params, q)];
    sums[q] = g.served == 0
                  ? (float4)(0.0f)
                  : rc_ic_gather(&grid, cell_start, cell_records, records, payloads, g.position.xyz,
                                 g.normal.xyz, params.accuracy, params.max_weight);
}

// Item q: radiance cache splatting at candidate q (rc_ic_candidate), camera sample i: the
// weighted sum over the records splatted into its tile, into the splat buffer sums[q]
// (ic_splat.h); 0 where the cache does not serve i.
RC_KERNEL void ic_splat(uint begin, uint end, IcParams params, SplatTileGrid tiles,
                        __global const int* tile_start, __global const int* tile_records,
                        __global const Record* records, __global const IrradiancePayload* payloads,
                        __global const GBufferSample* gbuffer, __global float4* sums) {
    RC_RANGE_ITEM(q);
    const uint i = rc_ic_candidate(&params, q);
    const GBufferSample g = gbuffer[i];
    sums[q] = g.served == 0 ? (float4)(0.0f)
                            : rc_ic_splat_sum(&params, &tiles, tile_start, tile_records, records,
                                              payloads, i, g.position.xyz, g.normal.xyz);
}

// Item i: camera sample i; marks used[r] = 1 for every record r of its tile's list that weighs
// it positively (the records that serve the image: temporal caching replaces only those when they
// expire, the report's "Replacement/Deletion Method"). Only the value 1 is ever written, so the
// result does not depend on the order.
RC_KERNEL void ic_records_used(uint begin, uint end, IcParams params, SplatTileGrid tiles,
                               __global const int* tile_start, __global const int* tile_records,
                               __global const Record* records,
                               __global const IrradiancePayload* payloads,
                               __global const GBufferSample* gbuffer, __global uint* used) {
    RC_RANGE_ITEM(i);
    const GBufferSample g = gbuffer[i];
    if (g.served == 0) {
        return;
    }
    const uint tile = rc_ic_sample_tile(&params, &tiles, i);
    for (int k = tile_start[tile]; k < tile_start[tile + 1]; ++k) {
        const int r = tile_records[k];
        if (rc_ic_weight(records + r, payloads + r, g.position.xyz, g.normal.xyz, params.accuracy,
                         params.max_weight) > 0.0f) {
            atomic_or(&used[r], 1u);
        }
    }
}

// The render pass (course, "Radiance Cache Splatting", Algorithm 2 step 5): every camera sample
// reads its entry of the splat buffer (ic_splat over every camera sample) for the diffuse lobe's
// cached light. Item = pixel: shades its camera samples and writes the pixel's means to film
// (RC_CACHED_FILM_SLOTS per pixel; rc_shade_pixel), the records overlay (from the world-space
// grid) as its layer. counters: [0] rays traced, [1] non-finite samples (dropped), [2] first
// pixel with one.
RC_KERNEL void ic_shade(uint begin, uint end, IcParams params, CameraParams camera,
                        RC_SCENE_PARAMETERS, RecordGrid grid, __global const int* cell_start,
                        __global const int* cell_records, __global const Record* records,
                        __global const IrradiancePayload* payloads, __global const float4* splat,
                        __global const RcGlossySample* glossy, __global float4* film,
                        __global uint* counters) {
    RC_RANGE_ITEM(pixel);
    const SceneData scene = RC_SCENE_DATA();
    const RecordCache cache = {grid,     cell_start,      cell_records,     records,
                               payloads, params.accuracy, params.max_weight};
    const PixelShader shader = {&scene, &camera, &params, &cache, splat, glossy};
    rc_shade_pixel(&shader, (uint)params.camera_spp, pixel, film, counters);
}
