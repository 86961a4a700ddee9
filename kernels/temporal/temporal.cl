// Entry kernels of temporal caching's reprojection (host/methods/temporal/tc_cells.cpp), for any
// record whose payload is computed from M x N hemisphere cells (irradiance records' cosine-weighted
// cells, radiance records' uniform ones: tc.cell_layout): a batch of records, their hemisphere
// samples carried to the next frame and assembled into the hemisphere the next frame is estimated
// to show them (temporal/tc_reprojection.h). The record's own reduction (ic_record_reduce,
// rc_record_project) then turns the assembled cells into its payload one frame later.
#include "common/kernel_range.h"
#include "scene_arguments.h"
#include "temporal/tc_reprojection.h"

// The cells' jitter of batch record b (random stream `stream`).
RC_FUNC TcCellJitter tc_record_jitter(const TcParams* tc, uint stream) {
    const TcCellJitter jitter = {tc->strata_m, tc->strata_n, tc->cell_layout,
                                 tc->key_lo,   tc->key_hi,   stream};
    return jitter;
}

// Item i: cell i % (M N) of batch record b = i / (M N), leaving origins[b] in the frame whose z
// axis is frames[b].xyz (random stream streams[b]), whose ray saw cells[i] = (L.rgb, distance)
// at this frame: carried[i], the sample carried to the next frame (rc_tc_carry_sample). Where
// surfaces[b].w is 1, a cell whose direction lies below the plane of surfaces[b].xyz (the
// surface's own normal) traced no ray and stays as it is.
RC_KERNEL void tc_carry_cells(uint begin, uint end, TcParams tc, RC_SCENE_PARAMETERS,
                              __global const float4* origins, __global const float4* frames,
                              __global const float4* surfaces, __global const uint* streams,
                              __global const float4* cells, __global const int* moved_slot,
                              __global const Triangle* moved_triangles,
                              __global const TcEmitter* emitters_now,
                              __global const TcEmitter* emitters_next,
                              __global TcCarriedSample* carried) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint per_record = (uint)(tc.strata_m * tc.strata_n);
    const uint b = i / per_record;
    const int cell = (int)(i % per_record);
    const float3 normal = frames[b].xyz;
    const TcCellJitter jitter = tc_record_jitter(&tc, streams[b]);
    const float3 direction = rc_tc_cell_direction(&jitter, cell, normal);
    if (surfaces[b].w != 0.0f && dot(direction, surfaces[b].xyz) <= 0.0f) {
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
    ray.origin = (float4)(origins[b].xyz, 0.0f);
    ray.direction = (float4)(direction, INFINITY);
    const MovedTriangles moved = {moved_slot, moved_triangles};
    carried[i] = rc_tc_carry_sample(&scene, moved, emitters_now, emitters_next, &tc, tc.strata_m,
                                    tc.strata_n, rc_ic_record_frame(normal), origins[b].xyz, cell,
                                    ray, cells[i]);
}

// Item b: batch record b's hemisphere at the next frame into next_cells (rc_tc_assemble; random
// stream streams[b]; marks: scratch, one per cell).
RC_KERNEL void tc_assemble_cells(uint begin, uint end, TcParams tc, __global const uint* streams,
                                 __global const TcCarriedSample* carried,
                                 __global const float4* cells, __global float4* next_cells,
                                 __global uint* marks) {
    RC_RANGE_ITEM(b);
    const size_t first = (size_t)b * (size_t)(tc.strata_m * tc.strata_n);
    const TcCellJitter jitter = tc_record_jitter(&tc, streams[b]);
    rc_tc_assemble(&jitter, tc.hole_passes, carried + first, cells + first, next_cells + first,
                   marks + first);
}
