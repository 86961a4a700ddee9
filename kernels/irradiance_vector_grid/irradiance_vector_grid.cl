// Entry kernels of the irradiance vector grid (host/methods/irradiance_vector_grid/: the grid,
// ivg_method.cpp): photon tracing, deposition of given segments (tests),
// normalisation, lookups (tests) and the render pass of `ivg` and `ivg-gather`.
#include "common/kernel_range.h"
#include "irradiance_vector_grid/ivg_photons.h"
#include "irradiance_vector_grid/ivg_shading.h"
#include "scene_arguments.h"

// Item i: photon params.first_photon + i, traced and deposited into accum (64-bit fixed point).
// counters[0] counts crossings, counters[1] rays.
RC_KERNEL void ivg_trace_photons(uint begin, uint end, IvgParams params, RC_SCENE_PARAMETERS,
                                 __global long* accum, __global uint* counters) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    uint rays = 0;
    const uint crossings =
        rc_ivg_trace_photon(&scene, &params, params.first_photon + i, accum, &rays);
    atomic_add(&counters[0], crossings);
    atomic_add(&counters[1], rays);
}

// Item i: the segment from[i] -> to[i] carrying flux[i].xyz, deposited into accum.
RC_KERNEL void ivg_deposit_segments(uint begin, uint end, IvgParams params,
                                    __global const float4* from, __global const float4* to,
                                    __global const float4* flux, __global long* accum) {
    RC_RANGE_ITEM(i);
    rc_ivg_deposit_segment(&params, from[i].xyz, to[i].xyz, flux[i].xyz, accum);
}

// Item v: vertex v's RC_IVG_VALUES_PER_VERTEX sums turned into irradiance vectors (§3.3): divided
// by the fixed-point units, the photon count and the area of the vertex's face cell for each
// direction.
RC_KERNEL void ivg_normalize(uint begin, uint end, IvgParams params, __global const long* accum,
                             __global float* values) {
    RC_RANGE_ITEM(v);
    const int columns = params.cells.x + 1;
    const int rows = params.cells.y + 1;
    const int i = (int)v % columns;
    const int j = ((int)v / columns) % rows;
    const int k = (int)v / (columns * rows);
    const float photons = (float)max(params.photon_count, 1u);
    for (int direction = 0; direction < 6; ++direction) {
        const float scale = ldexp(1.0f / (params.fixed_point_scale * photons *
                                          rc_ivg_face_area(&params, direction / 2, i, j, k)),
                                  -params.fixed_point_exponent);
        for (int n = 0; n < 9; ++n) {
            const size_t slot = ((size_t)v * 6 + (size_t)direction) * 9 + (size_t)n;
            values[slot] = (float)accum[slot] * scale;
        }
    }
}

// Item q: the irradiance (rgb) the grid gives point positions[q] with unit normal normals[q]
// (every corner taken as visible).
RC_KERNEL void ivg_lookup(uint begin, uint end, IvgParams params, __global const float* values,
                          __global const half* packed, __global const float4* positions,
                          __global const float4* normals, __global float4* out) {
    RC_RANGE_ITEM(q);
    out[q] =
        (float4)(rc_ivg_irradiance(&params, values, packed, positions[q].xyz, normals[q].xyz, 0xff),
                 0.0f);
}

// The render pass. Item = pixel: shades its params.camera_spp camera samples and writes the
// pixel's means to film (RC_CACHED_FILM_SLOTS per pixel; rc_shade_pixel), the grid's diffuse
// light at the camera's hit as its layer. counters: [0] rays, [1] NaN or infinite samples
// (dropped), [2] the first pixel that had one.
RC_KERNEL void ivg_shade(uint begin, uint end, IvgParams params, __global const float* values,
                         __global const half* packed, __global const IvgCellPlanes* cell_planes,
                         __global const IvgPlane* planes, CameraParams camera, RC_SCENE_PARAMETERS,
                         __global float4* film, __global uint* counters) {
    RC_RANGE_ITEM(pixel);
    const SceneData scene = RC_SCENE_DATA();
    const VectorGrid grid = {params, values, packed, cell_planes, planes};
    const PixelShader shader = {&scene, &grid, &camera};
    rc_shade_pixel(&shader, (uint)params.camera_spp, pixel, film, counters);
}
