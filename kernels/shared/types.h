// Plain structs shared by the host (C++) and the kernels (OpenCL C). Only float, int, uint, uchar
// arrays and 4-wide vectors, explicitly padded: no float3, whose size differs between host and
// device. tests/shared/shared_layout_test.cpp compares every layout listed in RC_SHARED_LAYOUTS on
// the device.
#pragma once

#include "compat.h"
#include "records.h"

// Leaf triangles in one BVH leaf at most; Embree's builder is told the same.
#define RC_BVH_MAX_LEAF_SIZE 8
// Depth bound given to Embree's builder; the traversal stack holds 3 entries per level.
#define RC_BVH_MAX_DEPTH 32
#define RC_BVH_STACK_SIZE (3 * RC_BVH_MAX_DEPTH + 1)
// The compressed wide BVH (WideBvhNode): children per node, triangles per leaf (in packets of
// four; a child's meta byte holds its packet count in 3 bits and its offset among the node's
// packets in 5), and the stack of its traversals: 7 entries per level.
#define RC_WIDE_BVH_WIDTH 8
#define RC_WIDE_BVH_MAX_LEAF_SIZE 8
#define RC_WIDE_BVH_STACK_SIZE ((RC_WIDE_BVH_WIDTH - 1) * RC_BVH_MAX_DEPTH + 1)
// The BVH layouts a program's traversal can be built for: the host's Context passes one as
// -DRC_BVH_LAYOUT to every program (host/device/bvh_layout.h, docs/bvh.md).
#define RC_BVH_LAYOUT_BVH4 1
#define RC_BVH_LAYOUT_WIDE 2
// Hit.primitive of a ray that hit nothing.
#define RC_NO_HIT 0xffffffffu

RC_SHARED_BEGIN

// A ray segment: points origin + t * direction for t in (tmin, tmax].
typedef struct Ray {
    float4 origin;     // xyz: origin, w: tmin
    float4 direction;  // xyz: direction (any length), w: tmax
} Ray;

// Closest hit of a ray: t, the scene's primitive index, and the barycentrics of vertices 1 and 2.
typedef struct Hit {
    float t;
    uint primitive;  // RC_NO_HIT when nothing was hit
    float u;
    float v;
} Hit;

// A 4-wide BVH node (docs/bvh.md): the bounds of its four children as float4 lanes, so one node
// is tested with six float4 operations. Child lane i is
//   child[i] >= 0: an inner node index;
//   child[i] <  0: a leaf of count[i] triangles starting at triangle index ~child[i];
// an unused lane has empty bounds (lower = +inf, upper = -inf), child 0 and count 0.
typedef struct BvhNode {
    float4 lower_x, upper_x;
    float4 lower_y, upper_y;
    float4 lower_z, upper_z;
    int4 child;
    int4 count;
} BvhNode;

// A node of the compressed 8-wide BVH (docs/bvh.md; after Ylitie, Karras and Laine, "Efficient
// Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs", HPG 2017, §3.1). Child i's box
// has the planes origin + q * 2^(exponent - 127) per axis, q the child's byte in lower_* and
// upper_*, rounded outwards when built, so the box holds the child's exact bounds. Inner
// children take the first slots, then leaves, then unused slots. Child i is
//   an inner node when bit i of inner_mask is set: node child_base + i;
//   a leaf when meta[i] is not 0: meta[i] >> 5 TrianglePackets from packet packet_base +
//   (meta[i] & 31), packets counted from the start of the node buffer (they follow the nodes);
//   unused otherwise (meta 0, an inverted box: lower 255, upper 0).
typedef struct WideBvhNode {
    float origin_x, origin_y, origin_z;
    uint child_base;
    uint packet_base;
    uchar exponent_x, exponent_y, exponent_z;
    uchar inner_mask;
    uchar meta[RC_WIDE_BVH_WIDTH];
    uchar lower_x[RC_WIDE_BVH_WIDTH];
    uchar upper_x[RC_WIDE_BVH_WIDTH];
    uchar lower_y[RC_WIDE_BVH_WIDTH];
    uchar upper_y[RC_WIDE_BVH_WIDTH];
    uchar lower_z[RC_WIDE_BVH_WIDTH];
    uchar upper_z[RC_WIDE_BVH_WIDTH];
} WideBvhNode;

// Up to four triangles of a leaf of the compressed wide BVH, by axis for a float4 test of all
// four at once (kernels/common/ray_triangle.h): v0[axis] holds that coordinate of the four
// triangles' first vertices. A leaf of fewer than four repeats its first triangle.
typedef struct TrianglePacket {
    float4 v0[3];
    float4 v1[3];
    float4 v2[3];
    uint4 primitive;  // the triangles' scene indices
} TrianglePacket;

// A triangle in BVH leaf order: its three vertices; v0.w holds the bits of its primitive index
// in the scene (rc_as_uint).
typedef struct Triangle {
    float4 v0, v1, v2;
} Triangle;

// Pixel reconstruction filters (CameraParams.filter; kernels/common/pixel_filter.h,
// docs/pixel-filters.md).
#define RC_FILTER_BOX 0
#define RC_FILTER_TENT 1
#define RC_FILTER_GAUSSIAN 2

// Pixel samplers (CameraParams.sampler): where a pixel's camera samples fall, before the filter
// (kernels/common/pixel_sampler.h).
#define RC_SAMPLER_INDEPENDENT 0
#define RC_SAMPLER_SOBOL 1

// A pinhole camera. The ray through image position (x, y) in pixels, (0, 0) the top-left corner,
// has direction top_left + right * x / width + down * y / height.
typedef struct CameraParams {
    float4 origin;        // xyz: eye
    float4 top_left;      // xyz: from the eye to the top-left image corner
    float4 right;         // xyz: the image's full width
    float4 down;          // xyz: the image's full height, top to bottom
    int4 resolution;      // x: width, y: height, in pixels
    int filter;           // RC_FILTER_*: the pixel filter camera samples are drawn from
    float filter_radius;  // its radius in pixels (along x and along y)
    int sampler;          // RC_SAMPLER_*: how the samples' (u, v) are drawn
    int pad1;
} CameraParams;

// Material models (Material.model).
#define RC_MATERIAL_DIFFUSE 0
#define RC_MATERIAL_PHONG 1
#define RC_MATERIAL_WARD 2
#define RC_MATERIAL_CONDUCTOR 3
#define RC_MATERIAL_DIELECTRIC 4
#define RC_MATERIAL_THIN_DIELECTRIC 5
#define RC_MATERIAL_DIFFUSE_TRANSMISSION 6

// A surface material (docs/scene-format.md). Two-sided; the dielectrics transmit.
typedef struct Material {
    float4 diffuse;             // rgb: diffuse reflectance (the Lambertian lobe); w: padding
    float4 specular;            // rgb: specular reflectance (conductor, dielectrics: a tint;
                                // diffuse transmission: its reflectance)
    float4 eta;                 // conductor: rgb, eta per channel; dielectrics: x, the index
    float4 k;                   // conductor: rgb, k per channel; diffuse transmission: rgb, T
    float exponent;             // Phong exponent
    float alpha_x;              // Ward or Trowbridge-Reitz roughness along the tangent
    float alpha_y;              // Ward or Trowbridge-Reitz roughness along the bitangent
    float diffuse_probability;  // probability of sampling the diffuse lobe
    int model;                  // RC_MATERIAL_*
    int texture;                // texture scaling the diffuse reflectance, or -1
    int texture_targets;        // diffuse transmission: which of its lobes the texture scales
                                // (RC_TEXTURE_SCALES_*); other models: 0, the diffuse one
    int pad1;
} Material;

// Material.texture_targets of a diffuse transmitter.
#define RC_TEXTURE_SCALES_REFLECTANCE 1
#define RC_TEXTURE_SCALES_TRANSMITTANCE 2

// Where a texture's texels (float4, linear RGB, rows top to bottom) lie in the texel array.
typedef struct TextureInfo {
    int first_texel;  // index of its top-left texel
    int width;        // in texels
    int height;       // in texels
    int pad0;
} TextureInfo;

// Shading data of a triangle, indexed by the scene primitive index.
typedef struct TriangleShading {
    int normal0;   // vertex 0's normal index; -1 in all three: the geometric normal
    int normal1;   // vertex 1's
    int normal2;   // vertex 2's
    int material;  // material index
    int uv0;       // vertex 0's texture-coordinate index; -1 in all three: none
    int uv1;       // vertex 1's
    int uv2;       // vertex 2's
    int light;     // area light index, or -1
} TriangleShading;

// Light kinds (Light.kind).
#define RC_LIGHT_AREA 0
#define RC_LIGHT_POINT 1
#define RC_LIGHT_SPOT 2
#define RC_LIGHT_CONSTANT 3
#define RC_LIGHT_DISTANT 4  // parallel light from one direction (the sun): a delta direction

typedef struct Light {
    float4 position;     // xyz (point, spot): position; w: padding
    float4 axis;         // xyz (spot, distant): unit direction the light travels; w: padding
    float4 radiance;     // rgb: radiance (area, constant), intensity (point, spot) or irradiance
                         // on a surface facing the light (distant); w: padding
    float area;          // area: total area
    float cutoff;        // spot: cutoff angle (radians)
    float beam;          // spot: beam width (radians)
    float cos_cutoff;    // spot: cosine of the cutoff angle
    float cos_beam;      // spot: cosine of the beam width
    int kind;            // RC_LIGHT_*
    int first_triangle;  // area: first entry in the light-triangle arrays
    int triangle_count;  // area: number of triangles
    // constant: its radiance map (common/environment_map.h), or map -1 for a uniform radiance.
    int map;               // the map's texture (texels radiance, scale applied), or -1
    int map_distribution;  // first entry of its sampling distribution in the light-triangle cdf
    int map_mapping;       // RC_MAP_*: how a direction finds its texel
    int pad0;
    float4 map_x;  // xyz: the rows of the map-from-world linear map (directions into the
    float4 map_y;  // map's frame); w: padding
    float4 map_z;
} Light;

// How an environment map's image covers the sphere of directions (Light.map_mapping).
#define RC_MAP_LATLONG 0     // longitude across, latitude down (common/environment_map.h)
#define RC_MAP_EQUAL_AREA 1  // Clarberg's equal-area octahedral square, as pbrt-v4's

// Per-pass parameters of the path tracer.
typedef struct PathTracerParams {
    int width;  // of the image, in pixels
    int height;
    int sample;  // index of the pass's sample (its random streams)
    int max_depth;
    int rr_depth;  // the depth where Russian roulette starts
    uint seed_lo;  // the 64-bit seed
    uint seed_hi;
    int pad0;
} PathTracerParams;

// The first hit of one camera sample (irradiance caching's G-buffer; sample s of pixel p is entry
// p * spp + s) or of one ray of a record's hemisphere (cell c of batch record b is entry
// b * M N + c; where the next cache level is read).
typedef struct GBufferSample {
    float4 position;  // xyz: hit point
    float4 normal;    // xyz: shading normal facing the ray
    float4 origin;    // xyz: where rays leaving the surface start (offset off it)
    float footprint;  // world size of a pixel (or of the hemisphere stratum's cone) at the hit
    float diffuse;    // diffuse reflectance there (luminance)
    int primitive;    // the primitive hit, or -1 (no hit)
    int served;       // 1 when the cache serves it (a hit with a diffuse lobe)
} GBufferSample;

// Random-number domain of irradiance-record sampling (kernels/caching/irradiance_records.h),
// kept apart from camera samples.
#define RC_IC_RNG_DOMAIN 0x49434331u

// Parameters of the irradiance-caching kernels.
typedef struct IcParams {
    int width;  // of the camera's image, in pixels
    int height;
    int camera_spp;      // camera samples per pixel
    int draw_records;    // 1 to draw the records overlay (ic_shade)
    int strata_m;        // M: polar strata of a record's hemisphere
    int strata_n;        // N: azimuthal strata
    int count_emission;  // 1 to count emission seen by hemisphere rays (tests)
    int max_depth;       // bounces of a path
    int rr_depth;        // the depth where Russian roulette starts
    int level;           // cache level of the records being computed (0: the camera's)
    int light_samples;   // next-event estimation's light samples at a camera hit (ic_shade)
    uint seed_lo;        // the 64-bit seed
    uint seed_hi;
    float accuracy;    // a: records influence points within a R
    float max_weight;  // the largest weight (near a record's centre)
    // A placement pass's candidates (ic_uncovered).
    int placement_stride;   // pixel stride (0: every entry)
    int placement_spp;      // camera samples per candidate pixel
    int placement_columns;  // candidate columns
    int glossy_cache;       // 1: the render pass reads the glossy lobes' light (RcGlossySample)
    int first_sample;       // camera sample s of a pixel is its sample first_sample + s
} IcParams;

// Irradiance vector grid interpolation (IvgParams::interpolation).
#define RC_IVG_TRILINEAR 0
#define RC_IVG_TRICUBIC 1

// Values per grid vertex: six directions (+x, -x, +y, -y, +z, -z), an irradiance vector (x, y, z)
// per colour channel (kernels/common/ivg_lookup.h gives the order).
#define RC_IVG_VALUES_PER_VERTEX 54
// Half floats per vertex in the compressed layout: per direction |I_r|, |I_g|, |I_b| and a unit
// direction (§4.2).
#define RC_IVG_PACKED_PER_VERTEX 36

// Parameters of the irradiance-vector-grid kernels (Pacanowski et al., INRIA RR-6983). The grid
// has cells.x x cells.y x cells.z voxels and (cells + 1) vertices along each axis; a vertex holds
// six irradiance vectors (+x, -x, +y, -y, +z, -z), one 3-vector per colour channel.
typedef struct IvgParams {
    float4 origin;         // xyz: the grid's lower corner
    float4 cell;           // xyz: the cell size along each axis
    float4 sphere_centre;  // xyz: centre of a sphere around the scene (environment photons)
    int4 cells;            // xyz: voxels along each axis
    float sphere_radius;   // radius of that sphere
    // Fixed-point units per unit of flux (deposition): fixed_point_scale * 2^fixed_point_exponent
    float fixed_point_scale;
    float min_cosine;  // the smallest |cosine| to a face's normal a crossing's weight is divided by
    int vertex_count;  // vertices in all
    uint photon_count;   // photons of the whole grid
    uint first_photon;   // first photon of the launch
    int include_direct;  // 1 to record unbounced (direct) segments
    int interpolation;   // RC_IVG_TRILINEAR or RC_IVG_TRICUBIC
    int compressed;      // 1 to read the compressed layout
    int max_depth;       // bounces of a camera path
    int rr_depth;        // the depth where Russian roulette starts
    int gather_rays;     // per camera sample (ivg-gather); 0: the grid read at the camera's hit
    int camera_spp;      // camera samples per pixel
    // The camera sample index of the render pass's first sample (a pass of a render by time
    // draws samples first_sample .. first_sample + camera_spp - 1)
    int first_sample;
    uint seed_lo;  // the 64-bit seed
    uint seed_hi;
    int light_samples;  // next-event estimation's light samples at a camera hit (ivg_shade)
    // Corner visibility without shadow rays (ivg_visibility.h, host: ivg_cell_planes.h): a
    // lookup uses its cell's planes only when its point and ray origin lie in the cell grown by
    // cell_margin, and a plane only when the origin lies on its free side by more than
    // origin_margin; it skips a corner's ray when the ray's target lies there by more than
    // cell_margin.
    float cell_margin;
    float origin_margin;
    // The power of two of the fixed-point units. Last, and filling the struct to the float4
    // alignment: rusticl (Mesa 22.3) takes a by-value struct argument's size without its
    // trailing padding and refuses the host's with CL_INVALID_ARG_SIZE.
    int fixed_point_exponent;
} IvgParams;

// A plane of the triangles overlapping a grid cell (grown by twice IvgParams::cell_margin) that
// has all of them on it or behind it: dot(equation.xyz, x) + equation.w is x's signed distance
// to it, positive on the free side (xyz: unit normal).
typedef struct IvgPlane {
    float4 equation;
} IvgPlane;

// A grid cell's supporting planes: indices into the IvgPlane table, -1 for none.
typedef struct IvgCellPlanes {
    int first;
    int second;
} IvgCellPlanes;

RC_SHARED_END

// Every shared struct and field, for the host/device layout comparison.
// clang-format off
#define RC_SHARED_LAYOUTS(STRUCT, FIELD)   \
    STRUCT(Ray)                            \
    FIELD(Ray, origin)                     \
    FIELD(Ray, direction)                  \
    STRUCT(Hit)                            \
    FIELD(Hit, t)                          \
    FIELD(Hit, primitive)                  \
    FIELD(Hit, u)                          \
    FIELD(Hit, v)                          \
    STRUCT(BvhNode)                        \
    FIELD(BvhNode, lower_x)                \
    FIELD(BvhNode, upper_x)                \
    FIELD(BvhNode, lower_y)                \
    FIELD(BvhNode, upper_y)                \
    FIELD(BvhNode, lower_z)                \
    FIELD(BvhNode, upper_z)                \
    FIELD(BvhNode, child)                  \
    FIELD(BvhNode, count)                  \
    STRUCT(WideBvhNode)                    \
    FIELD(WideBvhNode, origin_x)           \
    FIELD(WideBvhNode, origin_z)           \
    FIELD(WideBvhNode, child_base)         \
    FIELD(WideBvhNode, packet_base)        \
    FIELD(WideBvhNode, exponent_x)         \
    FIELD(WideBvhNode, exponent_z)         \
    FIELD(WideBvhNode, inner_mask)         \
    FIELD(WideBvhNode, meta)               \
    FIELD(WideBvhNode, lower_x)            \
    FIELD(WideBvhNode, upper_z)            \
    STRUCT(TrianglePacket)                 \
    FIELD(TrianglePacket, v0)              \
    FIELD(TrianglePacket, v1)              \
    FIELD(TrianglePacket, v2)              \
    FIELD(TrianglePacket, primitive)       \
    STRUCT(Triangle)                       \
    FIELD(Triangle, v0)                    \
    FIELD(Triangle, v1)                    \
    FIELD(Triangle, v2)                    \
    STRUCT(CameraParams)                   \
    FIELD(CameraParams, origin)            \
    FIELD(CameraParams, top_left)          \
    FIELD(CameraParams, right)             \
    FIELD(CameraParams, down)              \
    FIELD(CameraParams, resolution)        \
    FIELD(CameraParams, filter)            \
    FIELD(CameraParams, filter_radius)     \
    STRUCT(Material)                       \
    FIELD(Material, diffuse)               \
    FIELD(Material, specular)              \
    FIELD(Material, eta)                   \
    FIELD(Material, k)                     \
    FIELD(Material, exponent)              \
    FIELD(Material, alpha_x)               \
    FIELD(Material, alpha_y)               \
    FIELD(Material, diffuse_probability)   \
    FIELD(Material, model)                 \
    FIELD(Material, texture)               \
    STRUCT(TextureInfo)                    \
    FIELD(TextureInfo, first_texel)        \
    FIELD(TextureInfo, width)              \
    FIELD(TextureInfo, height)             \
    STRUCT(TriangleShading)                \
    FIELD(TriangleShading, normal0)        \
    FIELD(TriangleShading, normal1)        \
    FIELD(TriangleShading, normal2)        \
    FIELD(TriangleShading, material)       \
    FIELD(TriangleShading, uv0)            \
    FIELD(TriangleShading, uv1)            \
    FIELD(TriangleShading, uv2)            \
    FIELD(TriangleShading, light)          \
    STRUCT(Light)                          \
    FIELD(Light, position)                 \
    FIELD(Light, axis)                     \
    FIELD(Light, radiance)                 \
    FIELD(Light, area)                     \
    FIELD(Light, cutoff)                   \
    FIELD(Light, beam)                     \
    FIELD(Light, cos_cutoff)               \
    FIELD(Light, cos_beam)                 \
    FIELD(Light, kind)                     \
    FIELD(Light, first_triangle)           \
    FIELD(Light, triangle_count)           \
    FIELD(Light, map)                      \
    FIELD(Light, map_distribution)         \
    FIELD(Light, map_mapping)              \
    FIELD(Light, map_x)                    \
    FIELD(Light, map_y)                    \
    FIELD(Light, map_z)                    \
    STRUCT(PathTracerParams)               \
    FIELD(PathTracerParams, width)         \
    FIELD(PathTracerParams, height)        \
    FIELD(PathTracerParams, sample)        \
    FIELD(PathTracerParams, max_depth)     \
    FIELD(PathTracerParams, rr_depth)      \
    FIELD(PathTracerParams, seed_lo)       \
    FIELD(PathTracerParams, seed_hi)       \
    STRUCT(GBufferSample)                  \
    FIELD(GBufferSample, position)         \
    FIELD(GBufferSample, normal)           \
    FIELD(GBufferSample, origin)           \
    FIELD(GBufferSample, footprint)        \
    FIELD(GBufferSample, diffuse)          \
    FIELD(GBufferSample, primitive)        \
    FIELD(GBufferSample, served)           \
    RC_RECORD_LAYOUTS(STRUCT, FIELD)       \
    STRUCT(IcParams)                       \
    FIELD(IcParams, width)                 \
    FIELD(IcParams, height)                \
    FIELD(IcParams, camera_spp)            \
    FIELD(IcParams, draw_records)          \
    FIELD(IcParams, strata_m)              \
    FIELD(IcParams, strata_n)              \
    FIELD(IcParams, count_emission)        \
    FIELD(IcParams, max_depth)             \
    FIELD(IcParams, rr_depth)              \
    FIELD(IcParams, level)                 \
    FIELD(IcParams, light_samples)         \
    FIELD(IcParams, seed_lo)               \
    FIELD(IcParams, seed_hi)               \
    FIELD(IcParams, accuracy)              \
    FIELD(IcParams, max_weight)            \
    FIELD(IcParams, placement_stride)      \
    FIELD(IcParams, placement_spp)         \
    FIELD(IcParams, placement_columns)     \
    FIELD(IcParams, glossy_cache)          \
    FIELD(IcParams, first_sample)          \
    STRUCT(IvgParams)                      \
    FIELD(IvgParams, origin)               \
    FIELD(IvgParams, cell)                 \
    FIELD(IvgParams, sphere_centre)        \
    FIELD(IvgParams, cells)                \
    FIELD(IvgParams, sphere_radius)        \
    FIELD(IvgParams, fixed_point_scale)    \
    FIELD(IvgParams, min_cosine)           \
    FIELD(IvgParams, vertex_count)         \
    FIELD(IvgParams, photon_count)         \
    FIELD(IvgParams, first_photon)         \
    FIELD(IvgParams, include_direct)       \
    FIELD(IvgParams, interpolation)        \
    FIELD(IvgParams, compressed)           \
    FIELD(IvgParams, max_depth)            \
    FIELD(IvgParams, rr_depth)             \
    FIELD(IvgParams, gather_rays)          \
    FIELD(IvgParams, camera_spp)           \
    FIELD(IvgParams, first_sample)         \
    FIELD(IvgParams, seed_lo)              \
    FIELD(IvgParams, seed_hi)              \
    FIELD(IvgParams, light_samples)        \
    FIELD(IvgParams, cell_margin)          \
    FIELD(IvgParams, origin_margin)        \
    FIELD(IvgParams, fixed_point_exponent) \
    STRUCT(IvgPlane)                       \
    FIELD(IvgPlane, equation)              \
    STRUCT(IvgCellPlanes)                  \
    FIELD(IvgCellPlanes, first)            \
    FIELD(IvgCellPlanes, second)
// clang-format on

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::float4) == 16 && alignof(rc::shared::float4) == 16);
static_assert(sizeof(rc::shared::int4) == 16 && alignof(rc::shared::int4) == 16);
static_assert(sizeof(rc::shared::Ray) == 32);
static_assert(sizeof(rc::shared::Hit) == 16);
static_assert(sizeof(rc::shared::BvhNode) == 128);
static_assert(offsetof(rc::shared::BvhNode, child) == 96);
static_assert(sizeof(rc::shared::WideBvhNode) == 80);
static_assert(offsetof(rc::shared::WideBvhNode, meta) == 24);
static_assert(sizeof(rc::shared::TrianglePacket) == 160);
static_assert(sizeof(rc::shared::Triangle) == 48);
static_assert(sizeof(rc::shared::CameraParams) == 96);
static_assert(sizeof(rc::shared::Material) == 96);
static_assert(offsetof(rc::shared::Material, exponent) == 64);
static_assert(sizeof(rc::shared::TextureInfo) == 16);
static_assert(sizeof(rc::shared::TriangleShading) == 32);
static_assert(sizeof(rc::shared::Light) == 144);
static_assert(offsetof(rc::shared::Light, map_x) == 96);
static_assert(offsetof(rc::shared::Light, area) == 48);
static_assert(sizeof(rc::shared::PathTracerParams) == 32);
static_assert(sizeof(rc::shared::GBufferSample) == 64);
static_assert(sizeof(rc::shared::IcParams) == 80);
static_assert(sizeof(rc::shared::IvgParams) == 144);
static_assert(sizeof(rc::shared::IvgPlane) == 16);
static_assert(sizeof(rc::shared::IvgCellPlanes) == 8);
static_assert(offsetof(rc::shared::IvgParams, sphere_radius) == 64);
#endif
