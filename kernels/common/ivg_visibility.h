// Which corners of its cell a surface point sees, for the grid's lookup (docs/
// irradiance-vector-grid.md, "Corners the point cannot see are left out too"): a shadow ray from
// the point's ray origin to just short of each corner, except where one of the cell's supporting
// planes proves the ray unblocked. The host (host/methods/irradiance_vector_grid/
// ivg_cell_planes.h) stores per cell up to two planes of the triangles overlapping the cell
// (grown by twice params.cell_margin) that have all those triangles on or behind them. A shadow
// ray's segment stays inside the convex hull of the cell's corners and the ray origin, so when
// the origin lies in the cell grown by cell_margin, only those triangles can block it; when both
// of its ends lie strictly on a plane's free side, none of them can.
#pragma once

#include "common/ivg_lookup.h"
#include "common/path_radiance.h"

// Whether x lies in the cell at `base` grown by `margin` on every side.
RC_FUNC bool rc_ivg_in_grown_cell(const IvgParams* p, int3 base, float3 x, float margin) {
    const float3 lower = rc_ivg_corner_position(p, base, 0) - margin;
    const float3 upper = rc_ivg_corner_position(p, base, 7) + margin;
    return all(x >= lower) && all(x <= upper);
}

// The shadow ray's target for corner `corner`: just short of the corner, towards the origin.
RC_FUNC float3 rc_ivg_corner_target(const IvgParams* p, int3 base, int corner, float3 origin) {
    const float3 vertex = rc_ivg_corner_position(p, base, corner);
    return vertex + 0.01f * (origin - vertex);
}

// The corners (bit c: corner c) whose shadow ray from sp's origin one of the cell's supporting
// planes proves unblocked: the point and its ray origin lie in the cell grown by cell_margin, the
// origin lies on the plane's free side by more than origin_margin, and the corner's target by
// more than cell_margin (the whole segment then lies in the free side, every triangle that could
// block it on the plane or behind it).
RC_FUNC int rc_ivg_corners_in_front(const IvgParams* p, RC_GLOBAL const IvgCellPlanes* cell_planes,
                                    RC_GLOBAL const IvgPlane* planes, int3 base,
                                    const SurfacePoint* sp) {
    const IvgCellPlanes cell = cell_planes[(base.z * p->cells.y + base.y) * p->cells.x + base.x];
    if (cell.first < 0 || !rc_ivg_in_grown_cell(p, base, sp->position, p->cell_margin) ||
        !rc_ivg_in_grown_cell(p, base, sp->origin, p->cell_margin)) {
        return 0;
    }
    int front = 0;
    const int indices[2] = {cell.first, cell.second};
    for (int k = 0; k < 2; ++k) {
        if (indices[k] < 0) {
            continue;
        }
        const float4 e = planes[indices[k]].equation;
        if (!(dot(e.xyz, sp->origin) + e.w > p->origin_margin)) {
            continue;
        }
        for (int corner = 0; corner < 8; ++corner) {
            const float3 target = rc_ivg_corner_target(p, base, corner, sp->origin);
            if (dot(e.xyz, target) + e.w > p->cell_margin) {
                front |= 1 << corner;
            }
        }
    }
    return front;
}

// The corners of sp's cell the point sees (bit c: corner c, as rc_ivg_corner_position numbers
// them): those its cell's planes prove unblocked, and those whose shadow ray reaches them (each
// traced ray counted in *rays).
RC_FUNC int rc_ivg_visible_corners(const SceneData* scene, const IvgParams* p,
                                   RC_GLOBAL const IvgCellPlanes* cell_planes,
                                   RC_GLOBAL const IvgPlane* planes, const SurfacePoint* sp,
                                   uint* rays) {
    const int3 base = rc_ivg_cell_base(p, rc_ivg_grid_coordinates(p, sp->position));
    const int front = rc_ivg_corners_in_front(p, cell_planes, planes, base, sp);
    int visible = front;
    for (int corner = 0; corner < 8; ++corner) {
        if (((front >> corner) & 1) != 0) {
            continue;
        }
        const float3 target = rc_ivg_corner_target(p, base, corner, sp->origin);
        *rays += 1;
        if (!rc_occluded(scene, sp->origin, target, false, target - sp->origin)) {
            visible |= 1 << corner;
        }
    }
    return visible;
}
