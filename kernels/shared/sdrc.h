// What the host and the SDRC kernels share (DESIGN.md §6.5; Gassenbauer, Křivánek and Bouatouch,
// "Spatial Directional Radiance Caching", EGSR 2009, "SDRC" below): the L-tree node, a record's
// L-tree in the node array, the miss list and the kernels' parameters, and the encodings an
// L-tree node is made of (the paraboloid map, its 8-bit quantisation, Ward's RGBE), which compile
// on both sides.
#pragma once

#include "compat.h"

#ifndef __OPENCL_VERSION__
#include <cmath>
namespace rc::shared {
using std::fmax;
using std::fmin;  // the float overloads, as OpenCL C's
using std::sqrt;
}  // namespace rc::shared
#endif

// Cells per side of the quantised paraboloid map: SDRC §4.3 quantises a sample's position in D
// to 2 bytes, a 256 x 256 grid over [-1, 1]^2.
#define RC_LTREE_GRID 256

// LTreeNode.position's bookkeeping bits (SDRC §4.3: "2 bytes for bookkeeping information").
#define RC_LTREE_AXIS_SHIFT 16     // bit 16: the split axis of the subtree at the node (0: u, 1: v)
#define RC_LTREE_EMPTY (1u << 17)  // a direction no ray could sample (below the surface): no sample

// Largest nodes in one record's L-tree (tree and buffer): the traversal's stack bounds the depth.
#define RC_LTREE_MAX_NODES (1u << 22)
#define RC_LTREE_STACK 32

// Random-number domains of SDRC's record directions and interpolation directions, apart from
// every other stream.
#define RC_SDRC_RECORD_DOMAIN 0x53445231u
#define RC_SDRC_QUERY_DOMAIN 0x53445251u
// And of the uniform hemisphere cells temporal caching reprojects (sdrc_record_cells).
#define RC_SDRC_CELL_DOMAIN 0x53445243u

RC_SHARED_BEGIN

// One radiance sample of an L-tree (SDRC §4.3), 8 bytes.
typedef struct LTreeNode {
    uint radiance;  // Ward's RGBE: r | g << 8 | b << 16 | e << 24 (rc_rgbe_encode)
    uint position;  // bits 0-7: u, bits 8-15: v, the quantised paraboloid-map position in the
                    // record's frame (rc_ltree_quantise); bits 16-31: bookkeeping
                    // (RC_LTREE_AXIS_SHIFT, RC_LTREE_EMPTY)
} LTreeNode;

// Where record i's L-tree lies in the node array: a kd-tree over nodes [first_node, first_node +
// tree_nodes) in median order (the node of a range [lo, hi) is at lo + (hi - lo) / 2, its
// subtrees the ranges on either side, split along its axis bit), then the buffer of samples
// inserted since the last rebuild, [first_node + tree_nodes, + buffer_nodes), scanned linearly
// (SDRC §4.4: "We keep a buffer of added radiance samples; when it is full, the tree is rebuilt").
typedef struct SdrcTree {
    uint first_node;
    uint tree_nodes;
    uint buffer_nodes;
    uint pad0;
} SdrcTree;

// A direction of the interpolation no L-tree answered (SDRC §4.4 Algorithm 1): traced from the
// origin of `record` (chosen at random among the contributing records the direction lies above)
// and inserted into its L-tree, or from the camera sample itself when no record can take it.
typedef struct SdrcMiss {
    float4 direction;  // xyz: the world direction; w: f cos / (rho_s p), the sample's weight in
                       // the outgoing estimate (eq. 3) with unit specular reflectance
    uint sample;       // the camera sample (its glossy-buffer entry)
    uint index;        // j: which of the sample's M directions
    int record;        // the L-tree it is inserted into; -1: traced from the sample, not stored
    uint pad0;
} SdrcMiss;

// Parameters of SDRC's kernels.
typedef struct SdrcParams {
    int samples;         // N: directions of a new record (SDRC §4.3)
    int interp;          // M: directions of the interpolation per camera sample (§4.4)
    float pixel_interp;  // M times the camera samples per pixel: the directions a pixel draws,
                         // which the query radius adapts to (§4.4)
    float max_radius;    // r_max, the query radius' ceiling in D (§4.4: 0.15)
    uint seed_lo;        // the 64-bit seed
    uint seed_hi;
    float accuracy;      // a: records influence points within a R
    float max_weight;    // the largest spatial weight (near a record's centre)
    int max_depth;       // bounces of a path
    int rr_depth;        // the depth where Russian roulette starts
    int count_emission;  // 1 to count emission the rays see (tests)
    int pad0;
} SdrcParams;

RC_SHARED_END

// The SDRC structs and fields, for the host/device layout comparison
// (tests/shared/shared_layout_test.cpp).
// clang-format off
#define RC_SDRC_LAYOUTS(STRUCT, FIELD)  \
    STRUCT(LTreeNode)                   \
    FIELD(LTreeNode, radiance)          \
    FIELD(LTreeNode, position)          \
    STRUCT(SdrcTree)                    \
    FIELD(SdrcTree, first_node)         \
    FIELD(SdrcTree, tree_nodes)         \
    FIELD(SdrcTree, buffer_nodes)       \
    STRUCT(SdrcMiss)                    \
    FIELD(SdrcMiss, direction)          \
    FIELD(SdrcMiss, sample)             \
    FIELD(SdrcMiss, index)              \
    FIELD(SdrcMiss, record)             \
    STRUCT(SdrcParams)                  \
    FIELD(SdrcParams, samples)          \
    FIELD(SdrcParams, interp)           \
    FIELD(SdrcParams, pixel_interp)     \
    FIELD(SdrcParams, max_radius)       \
    FIELD(SdrcParams, seed_lo)          \
    FIELD(SdrcParams, seed_hi)          \
    FIELD(SdrcParams, accuracy)         \
    FIELD(SdrcParams, max_weight)       \
    FIELD(SdrcParams, max_depth)        \
    FIELD(SdrcParams, rr_depth)         \
    FIELD(SdrcParams, count_emission)
// clang-format on

RC_SHARED_BEGIN

// The paraboloid map of a direction of the upper hemisphere (z > 0) to the unit disc of D
// (Heidrich and Seidel, "View-independent Environment Maps", 1998; SDRC §4.3): (x, y) / (1 + z).
RC_FUNC void rc_paraboloid_map(float x, float y, float z, float* u, float* v) {
    *u = x / (1.0f + z);
    *v = y / (1.0f + z);
}

// Its inverse: the direction (2u, 2v, 1 - u^2 - v^2) / (1 + u^2 + v^2) of a point of the disc.
RC_FUNC void rc_paraboloid_unmap(float u, float v, float* x, float* y, float* z) {
    const float r2 = u * u + v * v;
    const float s = 1.0f / (1.0f + r2);
    *x = 2.0f * u * s;
    *y = 2.0f * v * s;
    *z = (1.0f - r2) * s;
}

// A coordinate of D ([-1, 1]) as its cell on the RC_LTREE_GRID grid, and the cell's centre.
RC_FUNC uint rc_ltree_quantise(float u) {
    const float cell = (u + 1.0f) * (0.5f * RC_LTREE_GRID);
    return cell <= 0.0f ? 0u : (cell >= RC_LTREE_GRID - 1 ? RC_LTREE_GRID - 1u : (uint)cell);
}

RC_FUNC float rc_ltree_centre(uint cell) {
    return ((float)cell + 0.5f) * (2.0f / RC_LTREE_GRID) - 1.0f;
}

RC_FUNC uint rc_ltree_node_u(uint position) { return position & 255u; }
RC_FUNC uint rc_ltree_node_v(uint position) { return (position >> 8) & 255u; }

// Ward's shared-exponent RGB (Ward, "Real Pixels", Graphics Gems II, 1991): with m the largest
// channel, m = f 2^e, f in [0.5, 1), each channel c is stored as floor(c 256 / 2^e) and e + 128;
// decoding returns the cell's centre, (byte + 0.5) 2^(e - 8), so every channel is within
// m / 256 of its value (the bound tests/sdrc/sdrc_ltree_test.cpp checks). Below 1e-32 (and for
// negative or NaN input) the colour is black, a NaN channel beside finite ones reads 0; m is
// capped below 2^127.
RC_FUNC uint rc_rgbe_encode(float r, float g, float b) {
    float m = fmax(fmax(r, g), b);  // fmax skips a NaN channel
    if (!(m >= 1e-32f)) {
        return 0u;
    }
    m = m < 1.7e38f ? m : 1.7e38f;
    const int e = (int)((rc_as_uint(m) >> 23) & 255u) - 126;     // m = f 2^e, f in [0.5, 1)
    const float scale = rc_as_float((uint)(127 + 8 - e) << 23);  // 2^(8 - e)
    const float c[3] = {r, g, b};
    uint bytes[3];
    for (int k = 0; k < 3; ++k) {
        const float x = c[k] > 0.0f ? fmin(c[k], m) * scale : 0.0f;
        bytes[k] = x >= 255.0f ? 255u : (uint)x;
    }
    return bytes[0] | bytes[1] << 8 | bytes[2] << 16 | (uint)(e + 128) << 24;
}

// The RGB of an RGBE word (black for 0).
RC_FUNC void rc_rgbe_decode(uint rgbe, float* r, float* g, float* b) {
    const uint stored = rgbe >> 24;
    if (stored == 0u) {
        *r = *g = *b = 0.0f;
        return;
    }
    const int e = (int)stored - 128;
    const float unit = rc_as_float((uint)(127 + e - 8) << 23);  // 2^(e - 8)
    *r = ((float)(rgbe & 255u) + 0.5f) * unit;
    *g = ((float)((rgbe >> 8) & 255u) + 0.5f) * unit;
    *b = ((float)((rgbe >> 16) & 255u) + 0.5f) * unit;
}

RC_SHARED_END

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::LTreeNode) == 8);
static_assert(sizeof(rc::shared::SdrcTree) == 16);
static_assert(sizeof(rc::shared::SdrcMiss) == 32);
static_assert(offsetof(rc::shared::SdrcMiss, record) == 24);
static_assert(sizeof(rc::shared::SdrcParams) == 48);
#endif
