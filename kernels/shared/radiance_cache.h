// What the host and the radiance-caching kernels share (DESIGN.md §6.4): the BRDF tables, one
// per material, of the cosine-weighted specular lobe's spherical-harmonic coefficients for
// outgoing directions on a parabolic-map grid (kernels/radiance_cache/rc_brdf_table.h).
#pragma once

#include "compat.h"
#include "spherical_harmonics.h"

// How radiance caching treats a material's reflection (BrdfTableInfo.kind): the automatic split
// of Křivánek et al., "Radiance Caching for Efficient Global Illumination Computation" (TVCG
// 2005), §4.1.
#define RC_BRDF_DIFFUSE 0   // no specular lobe: irradiance records serve it
#define RC_BRDF_GLOSSY 1    // some outgoing directions' lobes are represented at order <= n_max
#define RC_BRDF_FALLBACK 2  // no direction's lobe is: Monte Carlo importance sampling

// Random-number domain of radiance-record sampling (kernels/radiance_cache/rc_records.h), kept
// apart from camera samples and irradiance records.
#define RC_RC_RNG_DOMAIN 0x52434331u

RC_SHARED_BEGIN

// Where one material's table lies and what it holds. Texel (i, j) of a resolution x resolution
// grid over the parabolic map's square [-1, 1]^2 is texel t = j * resolution + i; its
// RC_SH_MAX_COEFFICIENTS coefficients are at coefficients[(first_texel + t) *
// RC_SH_MAX_COEFFICIENTS], its order (0: beyond n_max, Monte Carlo) at orders[first_texel + t].
typedef struct BrdfTableInfo {
    int first_texel;          // -1: no table (a diffuse material)
    int resolution;           // texels per side
    int order;                // the highest order any represented direction needs; 0 for none
    int kind;                 // RC_BRDF_*
    int basis;                // RC_BASIS_SH or RC_BASIS_HSH
    float max_error;          // the representation error every represented direction stays below
    float fallback_fraction;  // solid-angle fraction of outgoing directions left to Monte Carlo
    int pad0;
} BrdfTableInfo;

// What rc_brdf_table_texels computes for one material.
typedef struct BrdfTableParams {
    int first_texel;  // where this material's texels start in the output arrays
    int resolution;   // texels per side
    int basis;        // RC_BASIS_SH or RC_BASIS_HSH
    int theta_nodes;  // Gauss-Legendre nodes in cos(theta_i) over [0, 1]
    int phi_nodes;    // midpoint nodes in phi_i over [0, 2 pi)
    int pad0;
    int pad1;
    int pad2;
} BrdfTableParams;

// A camera sample as radiance caching sees it (rc_glossy_queries): the camera ray's hit with its
// shading frame and outgoing direction, and the order its material's BRDF table gives there.
typedef struct RcQuery {
    float4 position;          // xyz: the hit; w: 0
    float4 origin;            // xyz: where rays leaving the surface start; w: 0
    float4 normal;            // xyz: the shading frame's n (facing the camera ray); w: 0
    float4 tangent;           // xyz: the shading frame's t; w: 0
    float4 geometric_normal;  // xyz: the surface's own normal (facing the camera ray); w: 0
    float4 outgoing;          // xyz: w_o in the shading frame; w: 0
    float footprint;          // world size of a pixel at the hit
    int material;             // -1: no hit
    int order;      // the material's order where its table represents w_o's lobe; 0: Monte
                    // Carlo; -1: no specular lobe or no hit (radiance caching does not serve it)
    int primitive;  // the triangle hit (-1: none)
} RcQuery;

// A camera sample's glossy indirect light from a glossy cache (read by the render pass), with
// unit specular reflectance: radiance caching's rc_glossy_splat writes the sum over covering
// records of w <rotate(lambda + grad), b(w_o)> and sum w (0: no record covers the sample); SDRC's
// interpolation the lobe's estimate with weight 1. Order -1: no cache serves the sample's
// specular lobe (the render pass path traces it with the other lobes).
typedef struct RcGlossySample {
    float4 reflected;  // xyz: sum w L_o; w: 0
    float weight;      // sum w
    int order;         // RcQuery.order
    float hits;        // SDRC: fraction of the sample's directions answered from the L-trees
                       // (the sdrc-hits layer); 0 for radiance caching
    int rc_order;      // radiance caching: RcQuery.order (the rc-order layer); 0 for SDRC
} RcGlossySample;

// Parameters of radiance caching's record and splat kernels.
typedef struct RcParams {
    int order;     // n: the records' coefficient vectors have n^2 entries per channel
    int strata_m;  // M: polar strata of a record's hemisphere
    int strata_n;  // N: azimuthal strata
    uint seed_lo;  // the 64-bit seed
    uint seed_hi;
    float accuracy;      // a: records influence points within a R
    float max_weight;    // the largest weight (near a record's centre)
    int max_depth;       // bounces of a path
    int rr_depth;        // the depth where Russian roulette starts
    int count_emission;  // 1 to count emission the hemisphere rays see (tests)
    int pad0;
    int pad1;
} RcParams;

RC_SHARED_END

// The radiance-caching structs and fields, for the host/device layout comparison
// (tests/shared/shared_layout_test.cpp).
// clang-format off
#define RC_RADIANCE_CACHE_LAYOUTS(STRUCT, FIELD)    \
    STRUCT(BrdfTableInfo)                           \
    FIELD(BrdfTableInfo, first_texel)               \
    FIELD(BrdfTableInfo, resolution)                \
    FIELD(BrdfTableInfo, order)                     \
    FIELD(BrdfTableInfo, kind)                      \
    FIELD(BrdfTableInfo, basis)                     \
    FIELD(BrdfTableInfo, max_error)                 \
    FIELD(BrdfTableInfo, fallback_fraction)         \
    STRUCT(BrdfTableParams)                         \
    FIELD(BrdfTableParams, first_texel)             \
    FIELD(BrdfTableParams, resolution)              \
    FIELD(BrdfTableParams, basis)                   \
    FIELD(BrdfTableParams, theta_nodes)             \
    FIELD(BrdfTableParams, phi_nodes)               \
    STRUCT(RcQuery)                                 \
    FIELD(RcQuery, position)                        \
    FIELD(RcQuery, origin)                          \
    FIELD(RcQuery, normal)                          \
    FIELD(RcQuery, tangent)                         \
    FIELD(RcQuery, geometric_normal)                \
    FIELD(RcQuery, outgoing)                        \
    FIELD(RcQuery, footprint)                       \
    FIELD(RcQuery, material)                        \
    FIELD(RcQuery, order)                           \
    FIELD(RcQuery, primitive)                       \
    STRUCT(RcGlossySample)                          \
    FIELD(RcGlossySample, reflected)                \
    FIELD(RcGlossySample, weight)                   \
    FIELD(RcGlossySample, order)                    \
    FIELD(RcGlossySample, hits)                     \
    FIELD(RcGlossySample, rc_order)                 \
    STRUCT(RcParams)                                \
    FIELD(RcParams, order)                          \
    FIELD(RcParams, strata_m)                       \
    FIELD(RcParams, strata_n)                       \
    FIELD(RcParams, seed_lo)                        \
    FIELD(RcParams, seed_hi)                        \
    FIELD(RcParams, accuracy)                       \
    FIELD(RcParams, max_weight)                     \
    FIELD(RcParams, max_depth)                      \
    FIELD(RcParams, rr_depth)                       \
    FIELD(RcParams, count_emission)
// clang-format on

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::BrdfTableInfo) == 32);
static_assert(offsetof(rc::shared::BrdfTableInfo, max_error) == 20);
static_assert(sizeof(rc::shared::BrdfTableParams) == 32);
static_assert(sizeof(rc::shared::RcQuery) == 112);
static_assert(offsetof(rc::shared::RcQuery, footprint) == 96);
static_assert(sizeof(rc::shared::RcGlossySample) == 32);
static_assert(sizeof(rc::shared::RcParams) == 48);
#endif
