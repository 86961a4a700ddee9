// Temporal radiance caching (Gautron, Bouatouch and Pattanaik 2006; DESIGN.md §6.6;
// host/methods/temporal/) as the host and the kernels share it: the emitters of a frame as the
// unshadowed-light estimate sees them, the parameters of the reprojection, and one hemisphere
// sample carried to the next frame.
#pragma once

#include "compat.h"
#include "types.h"

RC_SHARED_BEGIN

// One emitter of a frame for the unshadowed irradiance (kernels/temporal/tc_unshadowed.h): a
// point, spot or constant-environment light as the renderer describes it (light.kind), or one
// triangle of an area light (light.kind RC_LIGHT_AREA, light.radiance its radiance, emitting on
// the side its winding v0 v1 v2 faces). A frame's list and the next frame's list describe the same
// emitters in the same order.
typedef struct TcEmitter {
    Light light;
    float4 v0;  // area: the triangle's vertices in world space; w: 0
    float4 v1;
    float4 v2;
} TcEmitter;

// Parameters of the reprojection kernels (kernels/temporal/temporal.cl).
typedef struct TcParams {
    float4 moving_lower;  // xyz: the bounds of the triangles that move, at this frame (lower >
    float4 moving_upper;  // upper when none does)
    int emitter_count;    // in each of the two emitter lists
    int hole_passes;      // 3 x 3 hole-filling passes (the report's §4.3)
    int emitters_change;  // 0: the two emitter lists are the same
    int cell_layout;      // the records' hemisphere cells: RC_TC_CELLS_COSINE or _UNIFORM
    int strata_m;         // the records' M x N hemisphere cells
    int strata_n;
    uint key_lo;  // the key of the cells' random streams (the jitter of their rays)
    uint key_hi;
} TcParams;

// How a record's M x N hemisphere cells divide it: irradiance caching's cosine-weighted strata
// (row j holds M sin^2 theta in [j, j + 1)) or radiance caching's uniform ones (M (1 - cos theta)).
#define RC_TC_CELLS_COSINE 0
#define RC_TC_CELLS_UNIFORM 1

// A record's hemisphere sample carried to the next frame (rc_tc_carry_sample).
typedef struct TcCarriedSample {
    float4 radiance;  // rgb: the radiance estimated to arrive at the next frame; w: 0
    float depth;      // its distance from the record's ray origin then (INFINITY: no hit)
    int cell;         // the hemisphere cell it arrives through then (-1: none, it left the
                      // record's hemisphere or turned its back)
    float row;        // the centre of the square it covers then, in continuous cell units
    float column;     // (rc_tc_carried_cell: its own cell carried by its motion)
    float size;       // the side of the square of cells it covers (0: it did not move and
                      // stands for its own cell alone)
    int pad0;
    int pad1;
    int pad2;
} TcCarriedSample;

RC_SHARED_END

// The temporal structs and fields, for the host/device layout comparison
// (tests/shared/shared_layout_test.cpp).
// clang-format off
#define RC_TEMPORAL_LAYOUTS(STRUCT, FIELD)   \
    STRUCT(TcEmitter)                        \
    FIELD(TcEmitter, light)                  \
    FIELD(TcEmitter, v0)                     \
    FIELD(TcEmitter, v1)                     \
    FIELD(TcEmitter, v2)                     \
    STRUCT(TcParams)                         \
    FIELD(TcParams, moving_lower)            \
    FIELD(TcParams, moving_upper)            \
    FIELD(TcParams, emitter_count)           \
    FIELD(TcParams, hole_passes)             \
    FIELD(TcParams, emitters_change)         \
    FIELD(TcParams, cell_layout)             \
    FIELD(TcParams, strata_m)                \
    FIELD(TcParams, strata_n)                \
    FIELD(TcParams, key_lo)                  \
    FIELD(TcParams, key_hi)                  \
    STRUCT(TcCarriedSample)                  \
    FIELD(TcCarriedSample, radiance)         \
    FIELD(TcCarriedSample, depth)            \
    FIELD(TcCarriedSample, cell)             \
    FIELD(TcCarriedSample, row)              \
    FIELD(TcCarriedSample, column)           \
    FIELD(TcCarriedSample, size)
// clang-format on

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::TcEmitter) == sizeof(rc::shared::Light) + 48);
static_assert(sizeof(rc::shared::TcParams) == 64);
static_assert(sizeof(rc::shared::TcCarriedSample) == 48);
#endif
