// The records of the caching methods (DESIGN.md §2, §6.2-6.5) as the host and the kernels share
// them. A record has two parts, kept in two arrays with the same index:
//   - Record, the part every caching method shares: where the record is, its normal and how far
//     it reaches (the validity radius R). The record store (host/methods/caching/), its record
//     grid and its cache file see only this part and the payload's size.
//   - the method's payload, what the record knows about the light: record i's payload is entry i
//     of the method's payload array. A fixed-size payload is a struct (IrradiancePayload, an
//     array of them); a payload whose size P is chosen at run time is P floats, record i's at
//     [i P, (i + 1) P) of a float array: radiance caching's n^2 spherical-harmonic coefficients
//     per channel and their two translational-gradient vectors (P = 3 n^2 + 2 x 3 n^2 for order
//     n). SDRC's records have no payload in the store: their L-trees (kernels/shared/sdrc.h) live
//     beside it, record i's described by entry i of an SdrcTree array.
// So the shared part, and everything written against it, does not depend on the method.
#pragma once

#include "compat.h"

RC_SHARED_BEGIN

// The shared part of a record.
typedef struct Record {
    float4 position;  // xyz: where the record was computed; w: 0
    float4 normal;    // xyz: the unit surface normal there; w: 0
    float radius;     // R, the validity radius after the [R_min, R_max] clamp; the record
                      // influences points within accuracy * R
    uint pad0;
    uint pad1;
    uint pad2;
} Record;

// Irradiance caching's payload (DESIGN.md §6.2): the indirect irradiance and its gradients per
// RGB channel, and where the nearest hemisphere hit lies beside the record.
typedef struct IrradiancePayload {
    float4 irradiance;  // rgb: E; w: 0
    float4 rotation_r;  // xyz: rotational gradient of the red channel (Ward and Heckbert 1992)
    float4 rotation_g;
    float4 rotation_b;
    float4 translation_r;  // xyz: translational gradient of the red channel
    float4 translation_g;
    float4 translation_b;
    float4 occluder;  // xyz: tangent-plane offset of the nearest hemisphere hit (rc_ic_weight)
} IrradiancePayload;

// A uniform world-space grid over records: cell c lists the records whose influence sphere
// touches it, as cell_records[cell_start[c] .. cell_start[c + 1]).
typedef struct RecordGrid {
    float4 origin;    // xyz: the lower corner
    float4 inv_cell;  // xyz: cells per unit length
    int4 dims;        // xyz: cells along each axis; w: total cells
} RecordGrid;

// Pixels per side of radiance cache splatting's screen tiles.
#define RC_SPLAT_TILE_SIZE 8

// Radiance cache splatting's screen tiles (host/methods/caching/splat_tiles.h): the
// image in tiles of tile_size pixels, tile (tx, ty) listing the records whose influence sphere's
// projection touches it as tile_records[tile_start[t] .. tile_start[t + 1]), t = ty tiles_x + tx.
typedef struct SplatTileGrid {
    int tile_size;  // pixels per tile side
    int tiles_x;
    int tiles_y;
    int pad0;
} SplatTileGrid;

// The nearest and farthest distance from the eye of the camera samples of one splat tile that
// the cache serves (ic_tile_depths); (+inf, -inf) when there is none.
typedef struct TileDepths {
    float nearest;
    float farthest;
} TileDepths;

RC_SHARED_END

// The record structs and fields, for RC_SHARED_LAYOUTS (kernels/shared/types.h).
// clang-format off
#define RC_RECORD_LAYOUTS(STRUCT, FIELD)      \
    STRUCT(Record)                            \
    FIELD(Record, position)                   \
    FIELD(Record, normal)                     \
    FIELD(Record, radius)                     \
    FIELD(Record, pad0)                       \
    STRUCT(IrradiancePayload)                 \
    FIELD(IrradiancePayload, irradiance)      \
    FIELD(IrradiancePayload, rotation_r)      \
    FIELD(IrradiancePayload, rotation_g)      \
    FIELD(IrradiancePayload, rotation_b)      \
    FIELD(IrradiancePayload, translation_r)   \
    FIELD(IrradiancePayload, translation_g)   \
    FIELD(IrradiancePayload, translation_b)   \
    FIELD(IrradiancePayload, occluder)        \
    STRUCT(RecordGrid)                        \
    FIELD(RecordGrid, origin)                 \
    FIELD(RecordGrid, inv_cell)               \
    FIELD(RecordGrid, dims)                   \
    STRUCT(SplatTileGrid)                     \
    FIELD(SplatTileGrid, tile_size)           \
    FIELD(SplatTileGrid, tiles_x)             \
    FIELD(SplatTileGrid, tiles_y)             \
    STRUCT(TileDepths)                        \
    FIELD(TileDepths, nearest)                \
    FIELD(TileDepths, farthest)
// clang-format on

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::Record) == 48);
static_assert(offsetof(rc::shared::Record, radius) == 32);
static_assert(sizeof(rc::shared::IrradiancePayload) == 128);
static_assert(sizeof(rc::shared::RecordGrid) == 48);
static_assert(sizeof(rc::shared::SplatTileGrid) == 16);
static_assert(sizeof(rc::shared::TileDepths) == 8);
#endif
