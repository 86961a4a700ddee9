// Entry kernels of temporal caching's reprojection for radiance records (`--method rc
// --temporal`; host/methods/temporal/tc_radiance_reprojection.cpp): a batch of radiance records'
// hemisphere samples (uniform cells, records/rc_hemisphere.h) carried to the next frame and
// assembled as temporal/tc_reprojection.h does for irradiance records; rc_record_project then
// projects the result as it projects a record's cells.
#include "radiance_cache/rc_records.h"
#include "scene_arguments.h"
#include "temporal/tc_reprojection.h"

// Item i: cell i % (M N) of batch record i / (M N) at sites[i / (M N)] (random stream
// streams[i / (M N)]), whose ray saw cells[i] = (L.rgb, distance) at this frame: carried[i], the
// sample carried to the next frame (rc_tc_carry_sample). A cell whose direction lies below the
// surface's own tangent plane traced no ray (rc_record_cells) and stays as it is.
__kernel void tc_carry_radiance_cells(uint begin, uint end, RcParams params, TcParams tc,
                                      RC_SCENE_PARAMETERS, __global const RcQuery* sites,
                                      __global const uint* streams, __global const float4* cells,
                                      __global const int* moved_slot,
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
    const int cell = (int)(i % per_record);
    const RcQuery site = sites[b];
    const float3 direction = rc_record_cell_direction(&params, streams[b], cell, site.normal.xyz);
    if (dot(direction, site.geometric_normal.xyz) <= 0.0f) {
        TcCarriedSample s;
        s.radiance = (float4)(cells[i].xyz, 0.0f);
        s.depth = cells[i].w;
        s.cell = cell;
        s.row = s.column = s.size = 0.0f;
        s.pad0 = s.pad1 = s.pad2 = 0;
        carried[i] = s;
        return;
    }
    Ray ray;
    ray.origin = (float4)(site.origin.xyz, 0.0f);
    ray.direction = (float4)(direction, INFINITY);
    const MovedTriangles moved = {moved_slot, moved_triangles};
    carried[i] = rc_tc_carry_sample(
        &scene, moved, emitters_now, emitters_next, &tc, params.strata_m, params.strata_n,
        rc_ic_record_frame(site.normal.xyz), site.origin.xyz, cell, ray, cells[i]);
}

// Item b: batch record b's hemisphere at the next frame into next_cells (rc_tc_assemble with the
// uniform cells' jittered grid; random stream streams[b]; marks: scratch, one per cell).
__kernel void tc_assemble_radiance_cells(uint begin, uint end, RcParams params, TcParams tc,
                                         __global const uint* streams,
                                         __global const TcCarriedSample* carried,
                                         __global const float4* cells, __global float4* next_cells,
                                         __global uint* marks) {
    const uint b = begin + (uint)get_global_id(0);
    if (b >= end) {
        return;
    }
    const size_t first = (size_t)b * (size_t)(params.strata_m * params.strata_n);
    uint key_lo, key_hi;
    rc_record_key(&params, &key_lo, &key_hi);
    const TcCellJitter jitter = {params.strata_m, params.strata_n, RC_TC_CELLS_UNIFORM,
                                 key_lo,          key_hi,          streams[b]};
    rc_tc_assemble(&jitter, tc.hole_passes, carried + first, cells + first, next_cells + first,
                   marks + first);
}
