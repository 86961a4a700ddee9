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

RC_SHARED_END

// The radiance-caching structs and fields, for the host/device layout comparison
// (tests/rc_layout_test.cpp).
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
    FIELD(BrdfTableParams, phi_nodes)
// clang-format on

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::BrdfTableInfo) == 32);
static_assert(offsetof(rc::shared::BrdfTableInfo, max_error) == 20);
static_assert(sizeof(rc::shared::BrdfTableParams) == 32);
#endif
