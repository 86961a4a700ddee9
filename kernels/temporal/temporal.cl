// Entry kernels of temporal caching's reprojection (host/methods/temporal/tc_reprojection.cpp):
// a batch of first-level irradiance records, their hemisphere samples carried to the next frame
// and assembled into the hemisphere the next frame is estimated to show them
// (temporal/tc_reprojection.h). ic_record_reduce then reduces it as it reduces a record's cells.
#include "scene_arguments.h"
#include "temporal/tc_reprojection.h"

// Item i: cell i % (M N) of batch record i / (M N) (random stream streams[i / (M N)]),
// whose ray saw cells[i] = (L.rgb, distance) at this frame: carried[i], the sample carried to the
// next frame (rc_tc_carry_sample).
__kernel void tc_carry_cells(uint begin, uint end, IcParams params, TcParams tc,
                             RC_SCENE_PARAMETERS, __global const Record* records,
                             __global const float4* origins, __global const uint* streams,
                             __global const float4* cells, __global const int* moved_slot,
                             __global const Triangle* moved_triangles,
                             __global const TcEmitter* emitters_now,
                             __global const TcEmitter* emitters_next,
                             __global TcCarriedSample* carried) {
    const uint i = begin + (uint)get_global_id(0);
    if (i >= end) {
        return;
    }
    const SceneData scene = RC_SCENE_DATA();
    const uint per_record = (uint)(params.strata_m * params.strata_n);
    const uint b = i / per_record;
    const uint cell = i % per_record;
    const float3 normal = records[b].normal.xyz;
    RngStream rng;
    const Ray ray = rc_ic_cell_ray(&params, streams[b], cell, normal, origins[b].xyz, &rng);
    const MovedTriangles moved = {moved_slot, moved_triangles};
    carried[i] = rc_tc_carry_sample(&scene, moved, emitters_now, emitters_next, &tc,
                                    params.strata_m, params.strata_n, rc_ic_record_frame(normal),
                                    origins[b].xyz, (int)cell, ray, cells[i]);
}

// Item b: batch record b's hemisphere at the next frame into next_cells (rc_tc_assemble; random
// stream streams[b]; marks: scratch, one per cell).
__kernel void tc_assemble_cells(uint begin, uint end, IcParams params, TcParams tc,
                                __global const uint* streams,
                                __global const TcCarriedSample* carried,
                                __global const float4* cells, __global float4* next_cells,
                                __global uint* marks) {
    const uint b = begin + (uint)get_global_id(0);
    if (b >= end) {
        return;
    }
    const size_t first = (size_t)b * (size_t)(params.strata_m * params.strata_n);
    const TcCellJitter jitter = {params.strata_m,          params.strata_n,
                                 RC_TC_CELLS_COSINE,       params.seed_lo ^ RC_IC_RNG_DOMAIN,
                                 rc_ic_level_key(&params), streams[b]};
    rc_tc_assemble(&jitter, tc.hole_passes, carried + first, cells + first, next_cells + first,
                   marks + first);
}
