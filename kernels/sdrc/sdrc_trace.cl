// Entry kernels of SDRC's rays (host/methods/sdrc/; DESIGN.md §6.5): a new record's N samples and
// the interpolation's misses, the light beyond each ray's hit read from the source the program is
// built for (records/radiance_source.h). The rays are the camera hit's first bounce: the emission
// they see is direct light, left to the render pass's next-event estimation unless the tests ask
// for it.
#include "common/kernel_range.h"
#include "scene_arguments.h"
#include "sdrc/sdrc_records.h"
#include "temporal/tc_reprojection.h"
// The source after the method's own headers (see records/radiance_source.h).
#include "caching/radiance_source.h"

// The light along a ray from `origin` in direction w (NaN or infinite radiance stored as black),
// its hit distance in w; rays counted into *rays.
RC_FUNC float4 rc_sdrc_trace(const SceneData* scene, const RadianceSource* source,
                             const SdrcParams* params, float3 origin, float3 w, RngStream* rng,
                             uint* rays) {
    Ray ray;
    ray.origin = (float4)(origin, 0.0f);
    ray.direction = (float4)(w, INFINITY);
    const SourceSample s = rc_source_radiance(scene, source, ray, rng, params->count_emission != 0,
                                              1, params->max_depth, params->rr_depth);
    *rays += s.rays;
    return (float4)(all(isfinite(s.radiance)) ? s.radiance : (float3)(0.0f), s.distance);
}

// Cell `cell` of the M x N uniform cells of the hemisphere of a record at `site` (random stream
// `stream`; the jitter keyed by RC_SDRC_CELL_DOMAIN, RC_TC_CELLS_UNIFORM): its (L.rgb, hit
// distance), black and infinitely far below the surface's own plane (no ray); rays counted into
// *rays. These are what temporal caching carries to the next frame (kernels/temporal/temporal.cl)
// to estimate the record's change (the report's §4.3): the L-tree's lobe-sampled directions fall
// in no cell grid.
RC_FUNC float4 rc_sdrc_cell(const SceneData* scene, const RadianceSource* source,
                            const SdrcParams* params, int m, int n, const RcQuery* site,
                            uint stream, int cell, uint* rays) {
    const uint key_lo = params->seed_lo ^ RC_SDRC_CELL_DOMAIN;
    const TcCellJitter jitter = {m, n, RC_TC_CELLS_UNIFORM, key_lo, params->seed_hi, stream};
    const float3 w = rc_tc_cell_direction(&jitter, cell, site->normal.xyz);
    if (dot(w, site->geometric_normal.xyz) <= 0.0f) {
        return (float4)(0.0f, 0.0f, 0.0f, INFINITY);
    }
    // Past the jitter's streams (one per row and column: indices below M N).
    RngStream rng = rc_rng_stream(key_lo, params->seed_hi, stream, (uint)cell + 0x40000000u);
    return rc_sdrc_trace(scene, source, params, site->origin.xyz, w, &rng, rays);
}

// Item i < sample_items (count N): sample i % N of batch record i / N (random stream
// streams[i / N]) at sites[i / N] (SDRC §4.3): its (L.rgb, hit distance) into samples[i] and its
// L-tree node into out_nodes[i]; a direction with no ray is infinitely far, black, and an empty
// node. Item sample_items + j (with temporal caching, M x N = cell_m x cell_n > 0): cell j % (M N)
// of record j / (M N) into cells[j] (rc_sdrc_cell). counters[0] counts the rays traced.
RC_KERNEL void sdrc_record_samples(uint begin, uint end, SdrcParams params, uint sample_items,
                                   int cell_m, int cell_n, RC_SCENE_PARAMETERS,
                                   __global const RcQuery* sites, __global const uint* streams,
                                   RC_RADIANCE_SOURCE_PARAMETERS __global float4* samples,
                                   __global LTreeNode* out_nodes, __global float4* cells,
                                   __global uint* counters) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const RadianceSource source = RC_RADIANCE_SOURCE_DATA();
    if (i >= sample_items) {
        const uint j = i - sample_items;
        const uint per_record = (uint)(cell_m * cell_n);
        const RcQuery site = sites[j / per_record];
        uint cell_rays = 0u;
        cells[j] = rc_sdrc_cell(&scene, &source, &params, cell_m, cell_n, &site,
                                streams[j / per_record], (int)(j % per_record), &cell_rays);
        atomic_add(&counters[0], cell_rays);
        return;
    }
    const uint n = (uint)params.samples;
    const uint b = i / n;
    const uint record = streams[b];
    const RcQuery site = sites[b];
    float3 w;
    float weight;
    if (!rc_sdrc_record_direction(&params, scene.materials, &site, record, i % n, &w, &weight)) {
        samples[i] = (float4)(0.0f, 0.0f, 0.0f, INFINITY);
        out_nodes[i].radiance = 0u;
        out_nodes[i].position = RC_LTREE_EMPTY;
        return;
    }
    uint key_lo, key_hi;
    rc_sdrc_record_key(&params, &key_lo, &key_hi);
    RngStream rng = rc_rng_stream(key_lo, key_hi, record, i % n);
    rc_rng_next_float(&rng);  // past the direction's words
    rc_rng_next_float(&rng);
    uint rays = 0u;
    const float4 s = rc_sdrc_trace(&scene, &source, &params, site.origin.xyz, w, &rng, &rays);
    atomic_add(&counters[0], rays);
    samples[i] = s;
    const Frame frame = rc_sdrc_record_frame(site.normal.xyz);
    out_nodes[i] = rc_sdrc_node(&frame, w, s.xyz);
}

// Item k: miss k (record -2: nothing to do): traced from its record's site (SDRC §4.4: "place the
// ray origin at the location of one of the L-trees"), or from its camera sample where no record
// could take it; the light into radiance[k], the node for the record's L-tree into out_nodes[k]
// (empty for a miss traced from the camera sample). The random stream: the sample's, past the
// interpolation's words. counters[0] counts the rays traced.
RC_KERNEL void sdrc_trace_misses(uint begin, uint end, SdrcParams params, RC_SCENE_PARAMETERS,
                                 __global const RcQuery* sites, __global const RcQuery* queries,
                                 __global const SdrcMiss* misses,
                                 RC_RADIANCE_SOURCE_PARAMETERS __global float4* radiance,
                                 __global LTreeNode* out_nodes, __global uint* counters) {
    RC_RANGE_ITEM(k);
    const SdrcMiss miss = misses[k];
    out_nodes[k].radiance = 0u;
    out_nodes[k].position = RC_LTREE_EMPTY;
    radiance[k] = (float4)(0.0f);
    if (miss.record == -2) {
        return;
    }
    const SceneData scene = RC_SCENE_DATA();
    const RadianceSource source = RC_RADIANCE_SOURCE_DATA();
    RngStream rng = rc_rng_stream(params.seed_lo ^ RC_SDRC_QUERY_DOMAIN, params.seed_hi,
                                  miss.sample, miss.index + 0x80000000u);
    const float3 origin =
        miss.record >= 0 ? sites[miss.record].origin.xyz : queries[miss.sample].origin.xyz;
    uint rays = 0u;
    radiance[k] = rc_sdrc_trace(&scene, &source, &params, origin, miss.direction.xyz, &rng, &rays);
    atomic_add(&counters[0], rays);
    if (miss.record >= 0) {
        const Frame frame = rc_sdrc_record_frame(sites[miss.record].normal.xyz);
        out_nodes[k] = rc_sdrc_node(&frame, miss.direction.xyz, radiance[k].xyz);
    }
}

// Item i: sample i % N of batch record i / N (random stream streams[i / N]) at sites[i / N],
// which saw samples[i] = (L.rgb, distance) at this frame: its radiance estimated at the next
// frame into next[i], L moved by the change of the uniform cell its direction passes through
// (next_cells - cells: rc_sdrc_cell's cells carried by temporal caching; L itself where the cell
// does not change), at least 0; a direction with no ray, or below the cells' hemisphere, keeps L.
RC_KERNEL void sdrc_record_next(uint begin, uint end, SdrcParams params, int m, int n,
                                __global const Material* materials, __global const RcQuery* sites,
                                __global const uint* streams, __global const float4* samples,
                                __global const float4* cells, __global const float4* next_cells,
                                __global float4* next) {
    RC_RANGE_ITEM(i);
    const uint b = i / (uint)params.samples;
    const RcQuery site = sites[b];
    const float4 seen = samples[i];
    next[i] = seen;
    float3 w;
    float weight;
    if (!rc_sdrc_record_direction(&params, materials, &site, streams[b], i % (uint)params.samples,
                                  &w, &weight)) {
        return;
    }
    const Frame frame = rc_sdrc_record_frame(site.normal.xyz);
    const int cell = rc_tc_cell_of(rc_to_local(&frame, w), m, n, RC_TC_CELLS_UNIFORM);
    if (cell < 0) {
        return;
    }
    const size_t c = (size_t)b * (size_t)(m * n) + (size_t)cell;
    next[i] = (float4)(fmax(seen.xyz + (next_cells[c].xyz - cells[c].xyz), (float3)(0.0f)), seen.w);
}
