// Plain structs shared by the host (C++) and the kernels (OpenCL C). Only float, int, uint and
// 4-wide vectors, explicitly padded: no float3, whose size differs between host and device.
// tests/shared_layout_test.cpp compares every layout listed in RC_SHARED_LAYOUTS on the device.
#pragma once

#include "compat.h"
#include "records.h"

// Leaf triangles in one BVH leaf at most; Embree's builder is told the same.
#define RC_BVH_MAX_LEAF_SIZE 8
// Depth bound given to Embree's builder; the traversal stack holds 3 entries per level.
#define RC_BVH_MAX_DEPTH 32
#define RC_BVH_STACK_SIZE (3 * RC_BVH_MAX_DEPTH + 1)
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

// A triangle in BVH leaf order: its three vertices; v0.w holds the bits of its primitive index
// in the scene (rc_as_uint).
typedef struct Triangle {
    float4 v0, v1, v2;
} Triangle;

// A pinhole camera. The ray through image position (x, y) in pixels, (0, 0) the top-left corner,
// has direction top_left + right * x / width + down * y / height.
typedef struct CameraParams {
    float4 origin;    // xyz: eye
    float4 top_left;  // xyz: from the eye to the top-left image corner
    float4 right;     // xyz: the image's full width
    float4 down;      // xyz: the image's full height, top to bottom
    int4 resolution;  // x: width, y: height, in pixels
} CameraParams;

// Material models (Material.kind.x).
#define RC_MATERIAL_DIFFUSE 0
#define RC_MATERIAL_PHONG 1
#define RC_MATERIAL_WARD 2

// A surface material (docs/scene-format.md). Two-sided and reflective only.
typedef struct Material {
    float4 diffuse;   // rgb: diffuse reflectance (the Lambertian lobe)
    float4 specular;  // rgb: specular reflectance; w: Phong exponent
    float4 lobe;      // x, y: Ward alpha_x, alpha_y; z: probability of sampling the diffuse lobe
    int4 kind;        // x: RC_MATERIAL_*; y: texture scaling the diffuse reflectance, or -1
} Material;

// Where a texture's texels (float4, linear RGB, rows top to bottom) lie in the texel array.
typedef struct TextureInfo {
    int4 layout;  // x: first texel, y: width, z: height
} TextureInfo;

// Shading data of a triangle, indexed by the scene primitive index.
typedef struct TriangleShading {
    int4 normals;  // xyz: vertex-normal indices (-1: the geometric normal); w: material index
    int4 uvs;      // xyz: texture-coordinate indices (-1: none); w: area light index or -1
} TriangleShading;

// Light kinds (Light.info.x).
#define RC_LIGHT_AREA 0
#define RC_LIGHT_POINT 1
#define RC_LIGHT_SPOT 2
#define RC_LIGHT_CONSTANT 3

typedef struct Light {
    float4 position;  // point, spot: xyz position
    float4 axis;      // spot: xyz unit axis, w: cosine of the cutoff angle
    float4 radiance;  // rgb: radiance (area, constant) or intensity (point, spot);
                      // w (spot): cosine of the beam width
    float4 shape;     // area: x: total area; spot: y: cutoff angle, z: beam width (radians)
    int4 info;        // x: RC_LIGHT_*; area: y: first entry in the light-triangle arrays,
                      // z: number of triangles
} Light;

// Per-pass parameters of the path tracer.
typedef struct PathTracerParams {
    int4 image;  // x: width, y: height, z: index of the pass's sample, w: unused
    int4 depth;  // x: maximum depth (bounces), y: depth where Russian roulette starts, z, w:
                 // unused
    uint4 seed;  // x, y: the 64-bit seed
} PathTracerParams;

// The first hit of one camera sample (irradiance caching's G-buffer; sample s of pixel p is entry
// p * spp + s) or of one ray of a record's hemisphere (where the next cache level is read).
typedef struct GBufferSample {
    float4 position;  // xyz: hit point; w: the footprint there (world size of a pixel, or of the
                      // hemisphere stratum's cone)
    float4 normal;    // xyz: shading normal facing the ray; w: diffuse reflectance (luminance)
    float4 origin;    // xyz: where rays leaving the surface start (offset off it)
    int4 info;        // x: primitive or -1 (no hit), y: pixel (record), z: sample (cell), w: 1
                      // when the cache serves it (a hit with a diffuse lobe)
} GBufferSample;

// Parameters of the irradiance-caching kernels.
typedef struct IcParams {
    int4 image;      // x: width, y: height, z: camera samples per pixel, w: record count
    int4 sampling;   // x: M (polar strata), y: N (azimuthal strata), z: first record of the
                     // launch, w: 1 to count emission seen by hemisphere rays (tests)
    int4 depth;      // x: maximum depth, y: Russian-roulette depth, z: cache level of the
                     // records being computed (0: the camera's), w: unused
    uint4 seed;      // x, y: the 64-bit seed
    float4 weights;  // x: accuracy a, y: largest weight (near a record's centre), z: 1 to draw
                     // the records overlay
    int4 placement;  // a placement pass's candidates: x: pixel stride, y: camera samples per
                     // candidate pixel, z: candidate columns, w: unused
} IcParams;

// Irradiance vector grid interpolation (IvgParams::lookup.x).
#define RC_IVG_TRILINEAR 0
#define RC_IVG_TRICUBIC 1

// Parameters of the irradiance-vector-grid kernels (Pacanowski et al., INRIA RR-6983). The grid
// has cells.x x cells.y x cells.z voxels and (cells + 1) vertices along each axis; a vertex holds
// six irradiance vectors (+x, -x, +y, -y, +z, -z), one 3-vector per colour channel.
typedef struct IvgParams {
    float4 origin;  // xyz: the grid's lower corner; w: fixed-point units per unit of flux
    float4 cell;    // xyz: the cell size along each axis; w: the smallest |cosine| to a face's
                    // normal a crossing's weight is divided by
    float4 sphere;  // xyz, w: centre and radius of a sphere around the scene (environment)
    int4 cells;     // xyz: voxels along each axis; w: vertices in all
    uint4 photons;  // x: photons of the whole grid, y: first photon of the launch, z: 1 to
                    // record unbounced (direct) segments, w: unused
    int4 depth;     // x: maximum depth (bounces of a camera path), y: Russian-roulette depth,
                    // z: gather rays per camera sample (ivg-gather), w: camera samples per pixel
    uint4 seed;     // x, y: the 64-bit seed
    int4 lookup;    // x: RC_IVG_TRILINEAR or RC_IVG_TRICUBIC, y: 1 to read the compressed
                    // layout, z, w: unused
} IvgParams;

RC_SHARED_END

// Every shared struct and field, for the host/device layout comparison.
// clang-format off
#define RC_SHARED_LAYOUTS(STRUCT, FIELD) \
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
    STRUCT(Material)                       \
    FIELD(Material, diffuse)               \
    FIELD(Material, specular)              \
    FIELD(Material, lobe)                  \
    FIELD(Material, kind)                  \
    STRUCT(TextureInfo)                    \
    FIELD(TextureInfo, layout)             \
    STRUCT(TriangleShading)                \
    FIELD(TriangleShading, normals)        \
    FIELD(TriangleShading, uvs)            \
    STRUCT(Light)                          \
    FIELD(Light, position)                 \
    FIELD(Light, axis)                     \
    FIELD(Light, radiance)                 \
    FIELD(Light, shape)                    \
    FIELD(Light, info)                     \
    STRUCT(PathTracerParams)               \
    FIELD(PathTracerParams, image)         \
    FIELD(PathTracerParams, depth)         \
    FIELD(PathTracerParams, seed)          \
    STRUCT(GBufferSample)                  \
    FIELD(GBufferSample, position)         \
    FIELD(GBufferSample, normal)           \
    FIELD(GBufferSample, origin)           \
    FIELD(GBufferSample, info)             \
    RC_RECORD_LAYOUTS(STRUCT, FIELD)       \
    STRUCT(IcParams)                       \
    FIELD(IcParams, image)                 \
    FIELD(IcParams, sampling)              \
    FIELD(IcParams, depth)                 \
    FIELD(IcParams, seed)                  \
    FIELD(IcParams, weights)               \
    FIELD(IcParams, placement)             \
    STRUCT(IvgParams)                      \
    FIELD(IvgParams, origin)               \
    FIELD(IvgParams, cell)                 \
    FIELD(IvgParams, sphere)               \
    FIELD(IvgParams, cells)                \
    FIELD(IvgParams, photons)              \
    FIELD(IvgParams, depth)                \
    FIELD(IvgParams, seed)                 \
    FIELD(IvgParams, lookup)
// clang-format on

#ifndef __OPENCL_VERSION__
static_assert(sizeof(rc::shared::float4) == 16 && alignof(rc::shared::float4) == 16);
static_assert(sizeof(rc::shared::int4) == 16 && alignof(rc::shared::int4) == 16);
static_assert(sizeof(rc::shared::Ray) == 32);
static_assert(sizeof(rc::shared::Hit) == 16);
static_assert(sizeof(rc::shared::BvhNode) == 128);
static_assert(offsetof(rc::shared::BvhNode, child) == 96);
static_assert(sizeof(rc::shared::Triangle) == 48);
static_assert(sizeof(rc::shared::CameraParams) == 80);
static_assert(sizeof(rc::shared::Material) == 64);
static_assert(sizeof(rc::shared::TextureInfo) == 16);
static_assert(sizeof(rc::shared::TriangleShading) == 32);
static_assert(sizeof(rc::shared::Light) == 80);
static_assert(sizeof(rc::shared::PathTracerParams) == 48);
static_assert(sizeof(rc::shared::GBufferSample) == 64);
static_assert(sizeof(rc::shared::IcParams) == 96);
static_assert(sizeof(rc::shared::IvgParams) == 128);
#endif
