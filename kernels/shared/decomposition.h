// What the host and the irradiance-decomposition kernels share (DESIGN.md §6.6b; Arikan, Forsyth
// and O'Brien, "Fast and Detailed Approximate Global Illumination by Irradiance Decomposition",
// SIGGRAPH 2005, reprinted in the course, "the paper" below): the kernels' parameters, a cluster
// of shading points and the rays that sample its distant radiance L_D* (§4.1), the fitted
// spherical-harmonic sample, the split triangles of the near field (§5) and the two terms of
// eq. 3 per camera sample.
#pragma once

#include "compat.h"

// Random-number domain of the decomposition's rays (cluster rays, triangle radiosity), kept apart
// from camera samples and every other method's streams.
#define RC_DECOMP_RNG_DOMAIN 0x44434d50u

// The far field's spherical harmonics: order 3 (bands 0-2), 9 functions, "only 9 coefficients
// provide a sufficient representation of the incoming radiance" for the diffuse component (§4,
// after Ramamoorthi and Hanrahan 2001).
#define RC_DECOMP_SH_ORDER 3
#define RC_DECOMP_SH_COEFFICIENTS 9

// The decomposition's film: the float4 slots its render pass writes per pixel (means over the
// pixel's finite camera samples).
#define RC_DECOMP_FILM_BEAUTY 0
#define RC_DECOMP_FILM_DIRECT 1
#define RC_DECOMP_FILM_INDIRECT 2
#define RC_DECOMP_FILM_ALBEDO 3
#define RC_DECOMP_FILM_NORMAL 4
#define RC_DECOMP_FILM_FAR 5   // rho_d / pi I_D: the distant term's reflected light
#define RC_DECOMP_FILM_NEAR 6  // rho_d / pi I_N: the near correction's (signed)
#define RC_DECOMP_FILM_SLOTS 7

// The near set's rule (DecompParams.near_set; --decomp-near; decomposition/decomp_near_set.h):
// the split triangles whose centroid lies within alpha (the paper's, §5), or those with any
// point within alpha.
#define RC_DECOMP_NEAR_CENTROID 0
#define RC_DECOMP_NEAR_TOUCHING 1

RC_SHARED_BEGIN

// Parameters of the decomposition's kernels.
typedef struct DecompParams {
    int width;  // of the camera's image, in pixels
    int height;
    int camera_spp;  // camera samples per pixel: the G-buffer's, where both terms are evaluated
    // Of those, the first this many are shaded fully (direct light, the other lobes); the others
    // add only the diffuse lobe's indirect light (--decomp-indirect-spp)
    int shaded_spp;
    // The camera sample index of the G-buffer's and the render pass's first sample (a pass of a
    // render by time draws samples first_sample .. first_sample + camera_spp - 1)
    int first_sample;
    int light_samples;  // next-event estimation's light samples at a camera hit (the render pass)
    int max_depth;      // bounces of a path
    int rr_depth;       // the depth where Russian roulette starts
    int cluster_rays;   // rays that sample one cluster's distant radiance (§4.1: 512)
    int radiosity_samples;  // points per split triangle of its radiosity B(t) (§6, pass 1)
    uint seed_lo;           // the 64-bit seed
    uint seed_hi;
    float alpha;          // the near/far distance (§3)
    float ridge;          // Tikhonov weight of the fit, per ray, relative to 1 / (4 pi)
    int count_emission;   // 1 to count emission the rays see (tests)
    int near_visibility;  // 1: a shadow ray tests each near triangle (--decomp-visibility rays)
    int gradients;  // 1: the fit adds translational gradients to the samples (--decomp-gradients)
    // Tikhonov weight of the fit's gradient part, per ray, relative to 1 / (4 pi), the offsets
    // in units of the kept origins' RMS distance from the centre (rc_decomp_fit_with_gradients)
    float gradient_ridge;
    int near_set;  // RC_DECOMP_NEAR_CENTROID or RC_DECOMP_NEAR_TOUCHING (--decomp-near)
} DecompParams;

// A cluster of shading points (§4.1) on the device: its members are G-buffer entries
// members[first_member .. first_member + member_count).
typedef struct DecompCluster {
    float4 centre;      // xyz: the members' mean position (where its sample is stored); w: 0
    float test_radius;  // the split test's sphere about the centre: the bounding sphere's
                        // radius times the split factor (§4.1's test: factor 1)
    uint first_member;  // into the member array
    uint member_count;
    uint stream;  // its random stream: clusters are numbered as the host creates them
} DecompCluster;

// One ray of a cluster's distant-radiance sampling (§4: "Rays whose intersections are closer to P
// than alpha are discarded").
typedef struct ClusterRay {
    float4 direction;  // xyz: the unit world direction; w: 0
    float4 offset;     // xyz: its origin less its cluster's centre (the fit's gradients); w: 0
    float4 radiance;   // rgb: the radiance it brings back (0 when discarded); w: 0
    int kept;          // 1: its hit lies at least alpha away (or it misses): it enters the fit
    int inside;        // 1: its hit lies inside the cluster's bounding sphere (§4.1's split test)
    // The split triangle (index into the near field's triangles) whose front its hit lies on, or
    // -1 (a miss, a back face, no split): --decomp-source radiosity reads B(t) there.
    int split_triangle;
    int pad1;
} ClusterRay;

// The far field's sample of one cluster: the least-squares fit of L_D* (§4) as 9 coefficients
// per colour channel, coefficient (l, m) at index l (l + 1) + m (shared/spherical_harmonics.h).
typedef struct ShSample {
    float4 coefficients[RC_DECOMP_SH_COEFFICIENTS];  // rgb per function; w: 0
} ShSample;

// The translational gradient of a far-field sample's coefficients: coefficient i at x is
// coefficients[i] + along_x[i] (x - c).x + along_y[i] (x - c).y + along_z[i] (x - c).z, c the
// sample's position (its cluster's centre), per colour channel. All zero without
// --decomp-gradients on.
typedef struct ShGradient {
    float4 along_x[RC_DECOMP_SH_COEFFICIENTS];  // rgb per function, per scene unit; w: 0
    float4 along_y[RC_DECOMP_SH_COEFFICIENTS];
    float4 along_z[RC_DECOMP_SH_COEFFICIENTS];
} ShGradient;

// A cluster's fit and what its rays saw.
typedef struct ClusterFit {
    ShSample sample;  // the coefficients at the cluster's centre
    ShGradient gradient;
    uint kept;    // rays in the fit
    uint inside;  // rays whose hit lies inside the bounding sphere
    uint pad0;
    uint pad1;
} ClusterFit;

// A triangle of the near field: the scene's triangles split until no edge exceeds alpha (§5).
// Its front is the side its winding's normal points to (the paper's back-facing test).
typedef struct NearTriangle {
    float4 v0;  // xyz: vertex 0; w: 0
    float4 v1;
    float4 v2;
    uint primitive;  // the scene triangle it was split from (the BVH's primitive index)
    uint pad0;
    uint pad1;
    uint pad2;
} NearTriangle;

// A node of the tree that splits one scene triangle into the near field's triangles
// (triangle_split.h), to find the split triangle a point of the scene triangle lies on: an inner
// node halves its triangle along the plane through its longest edge's midpoint and the opposite
// corner; a point x with dot(plane.xyz, x) + plane.w >= 0 lies in child `children`, the others in
// child `children` + 1. A leaf is split triangle `triangle`.
typedef struct SplitNode {
    float4 plane;  // xyz: the splitting plane's normal; w: its offset (inner nodes)
    int children;  // inner node: the first child's node index; leaf: -1
    int triangle;  // leaf: the split triangle's index; inner node: -1
    int pad0;
    int pad1;
} SplitNode;

// The two terms of eq. 3 at one camera sample: I_D from the interpolated far-field samples and
// the near correction I_N of eq. 4.
typedef struct DecompIrradiance {
    float4 far;        // rgb: I_D; w: 0
    float4 near;       // rgb: I_N (signed); w: 0
    uint near_count;   // triangles in the sum of eq. 4 (after the visibility test)
    uint far_samples;  // far-field samples with a positive weight
    uint near_rays;    // shadow rays of the visibility test (--decomp-visibility rays)
    uint pad0;
} DecompIrradiance;

RC_SHARED_END

// The decomposition's structs and fields, for the host/device layout comparison
// (tests/shared/shared_layout_test.cpp).
// clang-format off
#define RC_DECOMP_LAYOUTS(STRUCT, FIELD)        \
    STRUCT(DecompParams)                        \
    FIELD(DecompParams, width)                  \
    FIELD(DecompParams, height)                 \
    FIELD(DecompParams, camera_spp)             \
    FIELD(DecompParams, shaded_spp)             \
    FIELD(DecompParams, first_sample)           \
    FIELD(DecompParams, light_samples)          \
    FIELD(DecompParams, max_depth)              \
    FIELD(DecompParams, rr_depth)               \
    FIELD(DecompParams, cluster_rays)           \
    FIELD(DecompParams, radiosity_samples)      \
    FIELD(DecompParams, seed_lo)                \
    FIELD(DecompParams, seed_hi)                \
    FIELD(DecompParams, alpha)                  \
    FIELD(DecompParams, ridge)                  \
    FIELD(DecompParams, count_emission)         \
    FIELD(DecompParams, near_visibility)        \
    FIELD(DecompParams, gradients)              \
    FIELD(DecompParams, gradient_ridge)         \
    FIELD(DecompParams, near_set)               \
    STRUCT(DecompCluster)                       \
    FIELD(DecompCluster, centre)                \
    FIELD(DecompCluster, test_radius)           \
    FIELD(DecompCluster, first_member)          \
    FIELD(DecompCluster, member_count)          \
    FIELD(DecompCluster, stream)                \
    STRUCT(ClusterRay)                          \
    FIELD(ClusterRay, direction)                \
    FIELD(ClusterRay, offset)                   \
    FIELD(ClusterRay, radiance)                 \
    FIELD(ClusterRay, kept)                     \
    FIELD(ClusterRay, inside)                   \
    FIELD(ClusterRay, split_triangle)           \
    STRUCT(ShSample)                            \
    FIELD(ShSample, coefficients)               \
    STRUCT(ShGradient)                          \
    FIELD(ShGradient, along_x)                  \
    FIELD(ShGradient, along_y)                  \
    FIELD(ShGradient, along_z)                  \
    STRUCT(ClusterFit)                          \
    FIELD(ClusterFit, sample)                   \
    FIELD(ClusterFit, gradient)                 \
    FIELD(ClusterFit, kept)                     \
    FIELD(ClusterFit, inside)                   \
    STRUCT(NearTriangle)                        \
    FIELD(NearTriangle, v0)                     \
    FIELD(NearTriangle, v1)                     \
    FIELD(NearTriangle, v2)                     \
    FIELD(NearTriangle, primitive)              \
    STRUCT(SplitNode)                           \
    FIELD(SplitNode, plane)                     \
    FIELD(SplitNode, children)                  \
    FIELD(SplitNode, triangle)                  \
    STRUCT(DecompIrradiance)                    \
    FIELD(DecompIrradiance, far)                \
    FIELD(DecompIrradiance, near)               \
    FIELD(DecompIrradiance, near_count)         \
    FIELD(DecompIrradiance, far_samples)        \
    FIELD(DecompIrradiance, near_rays)
// clang-format on

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::DecompParams) == 76);
static_assert(sizeof(rc::shared::DecompCluster) == 32);
static_assert(sizeof(rc::shared::ClusterRay) == 64);
static_assert(sizeof(rc::shared::ShSample) == 144);
static_assert(sizeof(rc::shared::ShGradient) == 432);
static_assert(sizeof(rc::shared::ClusterFit) == 592);
static_assert(sizeof(rc::shared::NearTriangle) == 64);
static_assert(sizeof(rc::shared::SplitNode) == 32);
static_assert(sizeof(rc::shared::DecompIrradiance) == 48);
#endif
