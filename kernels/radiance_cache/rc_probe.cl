// Test kernels of radiance caching's foundations (tests/radiance_cache/,
// tests/shared/sh_*_test.cpp; `radcache bench sh`). Item index: begin + get_global_id(0).
#include "common/kernel_range.h"
#include "radiance_cache/rc_brdf_table.h"
#include "radiance_cache/rc_gradients.h"
#include "radiance_cache/rc_interpolation.h"
#include "radiance_cache/rc_projection.h"
#include "radiance_cache/rc_rotation.h"
#include "shared/radiance_cache.h"
#include "shared/sh_rotation_zxz.h"

// The basis functions of `basis` at directions[i] into out[i * order^2 ...].
RC_KERNEL void rc_basis_probe(uint begin, uint end, int basis, int order,
                              __global const float4* directions, __global float* out) {
    RC_RANGE_ITEM(i);
    float y[RC_SH_MAX_COEFFICIENTS];
    const float4 d = directions[i];
    rc_basis_eval(basis, d.x, d.y, d.z, order, y);
    const int count = rc_sh_count(order);
    for (int k = 0; k < count; ++k) {
        out[i * count + k] = y[k];
    }
}

// Test radiance of cells_probe: 0: `colour`; 1: colour * cos(theta)^exponent; 2: colour *
// function `function` of `basis` (a single basis function).
#define RC_PROBE_CONSTANT 0
#define RC_PROBE_COSINE_POWER 1
#define RC_PROBE_BASIS_FUNCTION 2

// Item i = record * m n + cell: the test radiance arriving from the direction of the cell, as a
// hemisphere ray of record `record` would bring it.
RC_KERNEL void rc_cells_probe(uint begin, uint end, int m, int n, uint key_lo, uint key_hi,
                              int mode, int basis, int function, float exponent, float4 colour,
                              __global float4* cells) {
    RC_RANGE_ITEM(i);
    const uint record = i / (uint)(m * n);
    const int cell = (int)(i % (uint)(m * n));
    const float3 d = rc_stratum_direction(key_lo, key_hi, record, cell, m, n);
    float scale = 1.0f;
    if (mode == RC_PROBE_COSINE_POWER) {
        scale = pow(d.z, exponent);
    } else if (mode == RC_PROBE_BASIS_FUNCTION) {
        float y[RC_SH_MAX_COEFFICIENTS];
        rc_basis_eval(basis, d.x, d.y, d.z, RC_SH_MAX_ORDER, y);
        scale = y[function];
    }
    cells[i] = (float4)(scale * colour.xyz, 0.0f);
}

// Item = record: rc_project_cells over the record's m n cells into out[record * 3 order^2 ...].
RC_KERNEL void rc_projection_probe(uint begin, uint end, int m, int n, uint key_lo, uint key_hi,
                                   int basis, int order, __global const float4* cells,
                                   __global float* out) {
    RC_RANGE_ITEM(record);
    float c[3 * RC_SH_MAX_COEFFICIENTS];
    rc_project_cells(cells + record * (uint)(m * n), m, n, key_lo, key_hi, record, basis, order, c);
    const int count = 3 * rc_sh_count(order);
    for (int k = 0; k < count; ++k) {
        out[record * count + k] = c[k];
    }
}

// The row-major 3 x 3 rotation of item i from rows rotations[3 i .. 3 i + 2].xyz.
void rc_probe_rotation(__global const float4* rotations, uint i, float r[9]) {
    for (int row = 0; row < 3; ++row) {
        const float4 v = rotations[3 * i + row];
        r[3 * row] = v.x;
        r[3 * row + 1] = v.y;
        r[3 * row + 2] = v.z;
    }
}

// Item i of the two rotation probes: rotates `vectors` coefficient vectors of order `order` at
// coefficients[i * vectors * order^2 ...] in place by the rotation whose rows are
// rotations[3 i .. 3 i + 2].xyz; by rc_sh_rotate, or where x90 is given by the zxzxz factorization
// (shared/sh_rotation_zxz.h) with that table of rc_sh_x90_table.
void rc_probe_rotate_item(uint i, int order, int vectors, __global const float4* rotations,
                          __global const float* x90, __global float* coefficients) {
    float r[9];
    rc_probe_rotation(rotations, i, r);
    const int count = rc_sh_count(order);
    float c[3 * RC_SH_MAX_COEFFICIENTS];
    for (int k = 0; k < vectors * count; ++k) {
        c[k] = coefficients[i * vectors * count + k];
    }
    if (x90 != 0) {
        rc_sh_rotate_zxz(r, x90, order, c, vectors, count);
    } else {
        rc_sh_rotate(r, order, c, vectors, count);
    }
    for (int k = 0; k < vectors * count; ++k) {
        coefficients[i * vectors * count + k] = c[k];
    }
}

// Item i: rc_probe_rotate_item by rc_sh_rotate.
RC_KERNEL void rc_rotation_probe(uint begin, uint end, int order, int vectors,
                                 __global const float4* rotations, __global float* coefficients) {
    RC_RANGE_ITEM(i);
    rc_probe_rotate_item(i, order, vectors, rotations, 0, coefficients);
}

// Item i: rc_probe_rotate_item by the zxzxz factorization with the table x90.
RC_KERNEL void rc_rotation_zxz_probe(uint begin, uint end, int order, int vectors,
                                     __global const float4* rotations, __global const float* x90,
                                     __global float* coefficients) {
    RC_RANGE_ITEM(i);
    rc_probe_rotate_item(i, order, vectors, rotations, x90, coefficients);
}

// Item i: the frame rotation from frame (rows from[3 i .. 3 i + 2]: t, b, n) to frame `to` into
// out[3 i .. 3 i + 2] (rows of R).
RC_KERNEL void rc_frame_rotation_probe(uint begin, uint end, __global const float4* from,
                                       __global const float4* to, __global float4* out) {
    RC_RANGE_ITEM(i);
    Frame a;
    a.t = from[3 * i].xyz;
    a.b = from[3 * i + 1].xyz;
    a.n = from[3 * i + 2].xyz;
    Frame b;
    b.t = to[3 * i].xyz;
    b.b = to[3 * i + 1].xyz;
    b.n = to[3 * i + 2].xyz;
    float r[9];
    rc_frame_rotation(&a, &b, r);
    for (int row = 0; row < 3; ++row) {
        out[3 * i + row] = (float4)(r[3 * row], r[3 * row + 1], r[3 * row + 2], 0.0f);
    }
}

// Item i: the table's coefficients (order^2) and order for the outgoing direction wo[i].
RC_KERNEL void rc_brdf_lookup_probe(uint begin, uint end, BrdfTableInfo info, int order,
                                    __global const float* coefficients, __global const int* orders,
                                    __global const float4* wo, __global float* out,
                                    __global int* out_orders) {
    RC_RANGE_ITEM(i);
    float c[RC_SH_MAX_COEFFICIENTS];
    rc_brdf_table_coefficients(coefficients, &info, wo[i].xyz, order, c);
    const int count = rc_sh_count(order);
    for (int k = 0; k < count; ++k) {
        out[i * count + k] = c[k];
    }
    out_orders[i] = rc_brdf_table_order(orders, &info, wo[i].xyz);
}

// Item i = record * m n + cell: the radiance and distance (w) that cell `cell`'s ray brings to a
// record at positions[record].xyz (frame = world axes) from the ceiling z = positions[record].w
// emitting spot(x, y) = exp(-(x^2 + y^2) / spot^2) * colour (the analytic scene of the gradient
// test). Every record draws the directions of stream `stream` (common random numbers).
RC_KERNEL void rc_ceiling_cells_probe(uint begin, uint end, int m, int n, uint key_lo, uint key_hi,
                                      uint stream, float spot, float4 colour,
                                      __global const float4* positions, __global float4* cells) {
    RC_RANGE_ITEM(i);
    const uint record = i / (uint)(m * n);
    const int cell = (int)(i % (uint)(m * n));
    const float3 d = rc_grid_stratum_direction(key_lo, key_hi, stream, cell, m, n);
    const float4 p = positions[record];
    const float t = (p.w - p.z) / d.z;
    const float x = p.x + t * d.x;
    const float y = p.y + t * d.y;
    const float radiance = exp(-(x * x + y * y) / (spot * spot));
    cells[i] = (float4)(radiance * colour.xyz, t);
}

// Item = record: rc_project_cells_with_gradients of the record's m n cells, directions of stream
// `stream`, into out[record * 9 order^2 ...]: coefficients (r, g, b) then gradients (r x, r y,
// g x, g y, b x, b y).
RC_KERNEL void rc_gradient_probe(uint begin, uint end, int m, int n, uint key_lo, uint key_hi,
                                 uint stream, int basis, int order, __global const float4* cells,
                                 __global float* out) {
    RC_RANGE_ITEM(record);
    float c[3 * RC_SH_MAX_COEFFICIENTS];
    float g[6 * RC_SH_MAX_COEFFICIENTS];
    rc_project_cells_with_gradients(cells + record * (uint)(m * n), m, n, key_lo, key_hi, stream,
                                    basis, order, c, g);
    const int count = rc_sh_count(order);
    for (int k = 0; k < 3 * count; ++k) {
        out[record * 9 * count + k] = c[k];
    }
    for (int k = 0; k < 6 * count; ++k) {
        out[record * 9 * count + 3 * count + k] = g[k];
    }
}

// Item i: rc_record_reflection of record records[i * 9 order^2 ...] (rc_gradient_probe's layout)
// at the query displaced by displacements[i].xy in the record's frame, whose frame the rotation
// rows rotations[3 i .. 3 i + 2] reach from the record's, for the outgoing direction wo[i] (query
// frame) of the material with table `info`: out[i].xyz.
RC_KERNEL void rc_reflection_probe(uint begin, uint end, int order, BrdfTableInfo info,
                                   __global const float* table, __global const float* x90,
                                   __global const float* records,
                                   __global const float4* displacements,
                                   __global const float4* rotations, __global const float4* wo,
                                   __global float4* out) {
    RC_RANGE_ITEM(i);
    const int count = rc_sh_count(order);
    float c[3 * RC_SH_MAX_COEFFICIENTS];
    float g[6 * RC_SH_MAX_COEFFICIENTS];
    for (int k = 0; k < 3 * count; ++k) {
        c[k] = records[i * 9 * count + k];
    }
    for (int k = 0; k < 6 * count; ++k) {
        g[k] = records[i * 9 * count + 3 * count + k];
    }
    float r[9];
    rc_probe_rotation(rotations, i, r);
    float brdf[RC_SH_MAX_COEFFICIENTS];
    rc_brdf_table_coefficients(table, &info, wo[i].xyz, order, brdf);
    const float3 reflected =
        rc_record_reflection(c, g, order, displacements[i].x, displacements[i].y, r, x90, brdf);
    out[i] = (float4)(reflected, 0.0f);
}
