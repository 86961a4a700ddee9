// Entry kernels of SDRC's queries, record radii and interpolation (host/methods/sdrc/; DESIGN.md
// §6.5). Item index: begin + get_global_id(0).
#include "common/kernel_range.h"
#include "scene_arguments.h"
#include "sdrc/sdrc_interpolation.h"

// Item i: camera sample i % spp of pixel i / spp (params.camera_spp) as SDRC sees it: order 1
// where its material has a specular lobe to cache (every glossy lobe: SDRC needs only the lobe's
// sampling, no representation of it), else -1; its glossy-buffer entry cleared (order -1: the
// render pass path traces the lobe until the interpolation fills the entry).
RC_KERNEL void sdrc_queries(uint begin, uint end, IcParams params, CameraParams camera,
                            RC_SCENE_PARAMETERS, __global RcQuery* queries,
                            __global RcGlossySample* glossy) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint spp = (uint)params.camera_spp;
    bool served;
    RcQuery q = rc_glossy_camera_query(&scene, &params, &camera, i / spp, i % spp, &served);
    q.order = served ? 1 : -1;
    queries[i] = q;
    RcGlossySample cleared;
    cleared.reflected = (float4)(0.0f);
    cleared.weight = 0.0f;
    cleared.order = -1;
    cleared.hits = 0.0f;
    cleared.rc_order = 0;
    glossy[i] = cleared;
}

// Item b: record b of a batch (random stream streams[b]) at sites[b], from its N samples in
// samples[b N ...]: rc_sdrc_record_radius into radii[b].
RC_KERNEL void sdrc_record_radius(uint begin, uint end, SdrcParams params,
                                  __global const Material* materials, __global const RcQuery* sites,
                                  __global const uint* streams, __global const float4* samples,
                                  __global float4* radii) {
    RC_RANGE_ITEM(b);
    const RcQuery site = sites[b];
    radii[b] = rc_sdrc_record_radius(&params, materials, &site, streams[b],
                                     samples + (size_t)b * (uint)params.samples);
}

// Item k: camera sample samples[k] (a sample of this interpolation round): its glossy-buffer entry
// (RcGlossySample: reflected = (1/M) sum of the answered directions' L~ f_s cos / (rho_s p),
// weight 1, order 1, hits the fraction of its M directions that need no ray; the misses' light is
// added by sdrc_add_misses) and its M miss slots misses[k M ...]. counters[0] counts the
// directions answered from the cache, counters[1] the L-trees range-queried.
RC_KERNEL void sdrc_interpolate(uint begin, uint end, SdrcParams params,
                                __global const Material* materials, RecordGrid grid,
                                __global const int* cell_start, __global const int* cell_records,
                                __global const Record* records, __global const RcQuery* sites,
                                __global const SdrcTree* trees, __global const LTreeNode* nodes,
                                __global const RcQuery* queries, __global const uint* samples,
                                __global RcGlossySample* glossy, __global SdrcMiss* misses,
                                __global uint* counters) {
    RC_RANGE_ITEM(k);
    SdrcCache cache;
    cache.grid = grid;
    cache.cell_start = cell_start;
    cache.cell_records = cell_records;
    cache.records = records;
    cache.sites = sites;
    cache.trees = trees;
    cache.nodes = nodes;
    const uint sample = samples[k];
    const RcQuery q = queries[sample];
    uint answered, range_queries;
    __global SdrcMiss* own = misses + (size_t)k * (uint)params.interp;
    const float3 sum =
        rc_sdrc_interpolate(&params, materials, &cache, &q, sample, own, &answered, &range_queries);
    int missed = 0;
    for (int j = 0; j < params.interp; ++j) {
        missed += own[j].record != -2 ? 1 : 0;
    }
    RcGlossySample out;
    out.reflected = (float4)(sum / (float)params.interp, 0.0f);
    out.weight = 1.0f;
    out.order = 1;
    out.hits = 1.0f - (float)missed / (float)params.interp;
    out.rc_order = 0;
    glossy[sample] = out;
    atomic_add(&counters[0], answered);
    atomic_add(&counters[1], range_queries);
}

// Item k: camera sample samples[k]: the light its misses (misses[k M ...], traced into
// radiance[k M ...]) bring, (1/M) sum L f_s cos / (rho_s p), added to its glossy-buffer entry in
// direction order.
RC_KERNEL void sdrc_add_misses(uint begin, uint end, SdrcParams params,
                               __global const uint* samples, __global const SdrcMiss* misses,
                               __global const float4* radiance, __global RcGlossySample* glossy) {
    RC_RANGE_ITEM(k);
    const size_t first = (size_t)k * (uint)params.interp;
    float3 sum = (float3)(0.0f);
    for (int j = 0; j < params.interp; ++j) {
        if (misses[first + j].record != -2) {
            sum += misses[first + j].direction.w * radiance[first + j].xyz;
        }
    }
    glossy[samples[k]].reflected.xyz += sum / (float)params.interp;
}
