// Entry kernels of radiance caching's records and interpolation (host/methods/radiance_cache/
// radiance_cache.h; DESIGN.md §6.4). Item index: begin + get_global_id(0).
#include "common/kernel_range.h"
#include "radiance_cache/rc_records.h"
#include "scene_arguments.h"

// Item i: camera sample i % spp of pixel i / spp (params.camera_spp) as radiance caching sees it
// (rc_camera_query).
RC_KERNEL void rc_glossy_queries(uint begin, uint end, IcParams params, CameraParams camera,
                                 RC_SCENE_PARAMETERS, __global const BrdfTableInfo* infos,
                                 __global const int* orders, __global RcQuery* queries) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint spp = (uint)params.camera_spp;
    queries[i] = rc_camera_query(&scene, &params, &camera, infos, orders, i / spp, i % spp);
}

// Item b: record b of a batch (random stream streams[b]) from its M N cells: its
// coefficient vectors and their translational gradients (rc_project_cells_with_gradients, SH at
// params.order) into payloads[b * 9 order^2 ...], and the harmonic mean (x) and minimum (y) of
// its hit distances into distances[b].
RC_KERNEL void rc_record_project(uint begin, uint end, RcParams params,
                                 __global const uint* streams, __global const float4* cells,
                                 __global float* payloads, __global float4* distances) {
    RC_RANGE_ITEM(b);
    const int per_record = params.strata_m * params.strata_n;
    __global const float4* own = cells + (size_t)b * (uint)per_record;
    uint key_lo, key_hi;
    rc_record_key(&params, &key_lo, &key_hi);
    float c[3 * RC_SH_MAX_COEFFICIENTS];
    float g[6 * RC_SH_MAX_COEFFICIENTS];
    rc_project_cells_with_gradients(own, params.strata_m, params.strata_n, key_lo, key_hi,
                                    streams[b], RC_BASIS_SH, params.order, c, g);
    const int count = rc_sh_count(params.order);
    __global float* out = payloads + (size_t)b * 9u * (uint)count;
    for (int k = 0; k < 3 * count; ++k) {
        out[k] = c[k];
    }
    for (int k = 0; k < 6 * count; ++k) {
        out[3 * count + k] = g[k];
    }
    distances[b] = (float4)(rc_record_distances(own, per_record), 0.0f, 0.0f);
}

// Item i: the glossy buffer's entry of camera sample i (RcGlossySample): for a query with a
// positive order, sum w <D(R)(lambda + dx dlambda/dx + dy dlambda/dy), b(w_o)> and sum w over the
// records the world-space grid lists at it, in list order (TVCG §4.4 eq. 12, §4.5 eq. 13; the
// radiance splat buffer's (L_o, w) pairs of "Radiance Cache Splatting", here gathered per
// sample). counters[0] counts the record reflections evaluated (each a rotation).
RC_KERNEL void rc_glossy_splat(uint begin, uint end, RcParams params, RecordGrid grid,
                               __global const int* cell_start, __global const int* cell_records,
                               __global const Record* records, __global const float* payloads,
                               __global const RcQuery* queries, __global const BrdfTableInfo* infos,
                               __global const float* table, __global const float* x90,
                               __global RcGlossySample* glossy, __global uint* counters) {
    RC_RANGE_ITEM(i);
    const RcQuery q = queries[i];
    RcGlossySample out;
    out.reflected = (float4)(0.0f);
    out.weight = 0.0f;
    out.order = q.order;
    out.hits = 0.0f;
    out.rc_order = q.order;
    const int cell = q.order > 0 ? rc_ic_grid_cell(&grid, q.position.xyz) : -1;
    if (cell >= 0) {
        const BrdfTableInfo info = infos[q.material];
        float brdf[RC_SH_MAX_COEFFICIENTS];
        const int order = q.order;
        rc_brdf_table_coefficients(table, &info, q.outgoing.xyz, order, brdf);
        const Frame frame = rc_query_frame(&q);
        const size_t stride = 9u * (uint)rc_sh_count(params.order);
        uint evaluated = 0;
        for (int k = cell_start[cell]; k < cell_start[cell + 1]; ++k) {
            __global const Record* record = records + cell_records[k];
            const float w = rc_record_weight(record, q.position.xyz, q.normal.xyz, params.accuracy,
                                             params.max_weight);
            if (w > 0.0f) {
                const float3 l = rc_covering_reflection(&params, record,
                                                        payloads + (size_t)cell_records[k] * stride,
                                                        &q, order, &frame, x90, brdf);
                out.reflected.xyz += w * l;
                out.weight += w;
                ++evaluated;
            }
        }
        atomic_add(&counters[0], evaluated);
    }
    glossy[i] = out;
}
