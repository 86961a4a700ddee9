// The irradiance vector grid (Pacanowski, Granier, Poulin and Schlick, INRIA RR-6983; DESIGN.md
// §6.3) as its readers see it: the vertex layout and the lookup of the irradiance a surface point
// receives. The deposition of photons is in ivg_deposit.h.
//
// Layout: vertex v = (k (cells.y + 1) + j) (cells.x + 1) + i holds RC_IVG_VALUES_PER_VERTEX
// values: direction d (0: +x, 1: -x, 2: +y, 3: -y, 4: +z, 5: -z), channel c (r, g, b), component
// (x, y, z) at ((v 6 + d) 3 + c) 3 + component. The "+x" vector holds the light that arrives from
// the +x side (photons travelling towards -x), which a surface facing +x receives. Accumulation is
// in 64-bit fixed point (fixed_point_scale * 2^fixed_point_exponent units per unit of flux), so
// sums do not depend on the order of the atomic additions; the normalised grid is float. The
// compressed layout keeps, per vertex and direction, RC_IVG_PACKED_PER_VERTEX / 6 half floats:
// |I_r|, |I_g|, |I_b| and the unit direction of I_r + I_g + I_b (§4.2).
#pragma once

#include "common/math.h"
#include "shared/types.h"

RC_FUNC float rc_ivg_component(float3 v, int axis) {
    return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

RC_FUNC int rc_ivg_cells_along(const IvgParams* p, int axis) {
    return axis == 0 ? p->cells.x : (axis == 1 ? p->cells.y : p->cells.z);
}

RC_FUNC int rc_ivg_vertex(const IvgParams* p, int i, int j, int k) {
    return (k * (p->cells.y + 1) + j) * (p->cells.x + 1) + i;
}

// The irradiance vectors (r, g, b) of direction `direction` at vertex (i, j, k), clamped to the
// grid, from the float or the compressed layout.
RC_FUNC void rc_ivg_vertex_vectors(const IvgParams* p, RC_GLOBAL const float* values,
                                   RC_GLOBAL const half* packed, int i, int j, int k, int direction,
                                   float3 out[3]) {
    i = clamp(i, 0, p->cells.x);
    j = clamp(j, 0, p->cells.y);
    k = clamp(k, 0, p->cells.z);
    const size_t v = (size_t)rc_ivg_vertex(p, i, j, k);
    if (p->compressed != 0) {
        const size_t base = (v * 6 + (size_t)direction) * 6;
        const float3 colour = vload_half3(0, packed + base);
        const float3 unit = vload_half3(0, packed + base + 3);
        out[0] = colour.x * unit;
        out[1] = colour.y * unit;
        out[2] = colour.z * unit;
        return;
    }
    const size_t base = (v * 6 + (size_t)direction) * 9;
    for (int c = 0; c < 3; ++c) {
        out[c] = vload3(0, values + base + 3 * (size_t)c);
    }
}

// Catmull-Rom weights of the four vertices around fraction t in [0, 1] (interpolating, exact
// for quadratic fields).
RC_FUNC float4 rc_ivg_cubic_weights(float t) {
    const float t2 = t * t;
    const float t3 = t2 * t;
    return (float4)(0.5f * (-t3 + 2.0f * t2 - t), 0.5f * (3.0f * t3 - 5.0f * t2 + 2.0f),
                    0.5f * (-3.0f * t3 + 4.0f * t2 + t), 0.5f * (t3 - t2));
}

// Grid coordinates (position in cells, clamped to the grid) of point x, and the lower corner of
// the cell interpolation uses there.
RC_FUNC float3 rc_ivg_grid_coordinates(const IvgParams* p, float3 x) {
    const float3 upper = (float3)((float)p->cells.x, (float)p->cells.y, (float)p->cells.z);
    return clamp((x - p->origin.xyz) / p->cell.xyz, (float3)(0.0f), upper);
}

RC_FUNC int3 rc_ivg_cell_base(const IvgParams* p, float3 g) {
    return (int3)(min((int)floor(g.x), max(p->cells.x - 1, 0)),
                  min((int)floor(g.y), max(p->cells.y - 1, 0)),
                  min((int)floor(g.z), max(p->cells.z - 1, 0)));
}

// World position of corner `corner` (bit 0: +x, bit 1: +y, bit 2: +z) of the cell at `base`.
RC_FUNC float3 rc_ivg_corner_position(const IvgParams* p, int3 base, int corner) {
    const float3 index =
        (float3)((float)(base.x + (corner & 1)), (float)(base.y + ((corner >> 1) & 1)),
                 (float)(base.z + ((corner >> 2) & 1)));
    return p->origin.xyz + index * p->cell.xyz;
}

// Whether a vertex's vectors for one direction hold anything: no photon crossed its face cell
// in that direction when all are zero (inside a solid, behind a wall off the grid planes).
RC_FUNC bool rc_ivg_reached(const float3 vectors[3]) {
    return any(vectors[0] != 0.0f) || any(vectors[1] != 0.0f) || any(vectors[2] != 0.0f);
}

// The irradiance vectors (r, g, b) of one direction spatially interpolated at grid coordinate g
// (position in cells): trilinear over the cell's corners that photons reached and `visible` (bit
// c: corner c, as rc_ivg_corner_position numbers them) lets through, the weights renormalised
// over them (a vertex no photon reached, inside a solid or behind a wall that does not lie on a
// grid plane, carries no information about the surface point and would darken it; one the point
// cannot see lies behind a wall and would carry the other side's light), or tricubic (Catmull-Rom,
// vertices beyond the grid clamped) when all 8 corners are visible and all 64 vertices of its
// stencil were reached, trilinear otherwise.
RC_FUNC void rc_ivg_interpolate(const IvgParams* p, RC_GLOBAL const float* values,
                                RC_GLOBAL const half* packed, float3 g, int direction, int visible,
                                float3 out[3]) {
    out[0] = out[1] = out[2] = (float3)(0.0f);
    const int3 base = rc_ivg_cell_base(p, g);
    const float3 t = g - (float3)((float)base.x, (float)base.y, (float)base.z);
    float3 vectors[3];
    if (p->interpolation == RC_IVG_TRICUBIC && visible == 0xff) {
        const float4 wx = rc_ivg_cubic_weights(t.x);
        const float4 wy = rc_ivg_cubic_weights(t.y);
        const float4 wz = rc_ivg_cubic_weights(t.z);
        const float ax[4] = {wx.x, wx.y, wx.z, wx.w};
        const float ay[4] = {wy.x, wy.y, wy.z, wy.w};
        const float az[4] = {wz.x, wz.y, wz.z, wz.w};
        bool complete = true;
        for (int dz = 0; dz < 4 && complete; ++dz) {
            for (int dy = 0; dy < 4 && complete; ++dy) {
                for (int dx = 0; dx < 4 && complete; ++dx) {
                    const float weight = ax[dx] * ay[dy] * az[dz];
                    rc_ivg_vertex_vectors(p, values, packed, base.x + dx - 1, base.y + dy - 1,
                                          base.z + dz - 1, direction, vectors);
                    complete = rc_ivg_reached(vectors);
                    for (int c = 0; c < 3; ++c) {
                        out[c] += weight * vectors[c];
                    }
                }
            }
        }
        if (complete) {
            return;
        }
        out[0] = out[1] = out[2] = (float3)(0.0f);
    }
    float total = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1;
        const int dy = (corner >> 1) & 1;
        const int dz = (corner >> 2) & 1;
        const float weight =
            (dx ? t.x : 1.0f - t.x) * (dy ? t.y : 1.0f - t.y) * (dz ? t.z : 1.0f - t.z);
        if (((visible >> corner) & 1) == 0) {
            continue;
        }
        rc_ivg_vertex_vectors(p, values, packed, base.x + dx, base.y + dy, base.z + dz, direction,
                              vectors);
        if (!rc_ivg_reached(vectors)) {
            continue;
        }
        total += weight;
        for (int c = 0; c < 3; ++c) {
            out[c] += weight * vectors[c];
        }
    }
    if (total > 0.0f) {
        for (int c = 0; c < 3; ++c) {
            out[c] /= total;
        }
    }
}

// Irradiance (r, g, b) at point x with unit normal n (§4.1): per axis the vector of the side the
// normal faces, spatially interpolated (over the corners `visible` lets through), blended as
// I_n = I_x n_x^2 + I_y n_y^2 + I_z n_z^2, and E = max(0, <I_n, n>) per channel. The reflected
// radiance of a Lambertian surface is rho / pi E.
RC_FUNC float3 rc_ivg_irradiance(const IvgParams* p, RC_GLOBAL const float* values,
                                 RC_GLOBAL const half* packed, float3 x, float3 n, int visible) {
    const float3 g = rc_ivg_grid_coordinates(p, x);
    float3 blended[3] = {(float3)(0.0f), (float3)(0.0f), (float3)(0.0f)};
    for (int axis = 0; axis < 3; ++axis) {
        const float n_a = rc_ivg_component(n, axis);
        const float weight = n_a * n_a;
        if (weight == 0.0f) {
            continue;
        }
        float3 vectors[3];
        rc_ivg_interpolate(p, values, packed, g, 2 * axis + (n_a >= 0.0f ? 0 : 1), visible,
                           vectors);
        for (int c = 0; c < 3; ++c) {
            blended[c] += weight * vectors[c];
        }
    }
    return (float3)(fmax(0.0f, dot(blended[0], n)), fmax(0.0f, dot(blended[1], n)),
                    fmax(0.0f, dot(blended[2], n)));
}
