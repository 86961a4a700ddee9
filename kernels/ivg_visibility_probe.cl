// Test kernel (tests/irradiance_vector_grid/ivg_visibility_test.cpp): the corners of its grid cell
// a lookup's surface point sees, by rc_ivg_visible_corners (the cell's supporting planes, shadow
// rays for the rest) and by a shadow ray to every corner, as the lookup traced them before the
// cells had planes.
#include "common/ivg_visibility.h"
#include "common/kernel_range.h"
#include "scene_arguments.h"

// Item i: at the first hit of rays[i], out[i] = (corners seen by rc_ivg_visible_corners, corners
// seen by eight shadow rays, the rays rc_ivg_visible_corners traced, 1); all 0 without a hit.
RC_KERNEL void ivg_visibility_probe(uint begin, uint end, IvgParams params,
                                    __global const float* values, __global const half* packed,
                                    __global const IvgCellPlanes* cell_planes,
                                    __global const IvgPlane* planes, RC_SCENE_PARAMETERS,
                                    __global const Ray* rays, __global uint4* out) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const Ray ray = rays[i];
    const Hit hit = rc_trace_closest(nodes, triangles, ray);
    if (hit.primitive == RC_NO_HIT) {
        out[i] = (uint4)(0u);
        return;
    }
    const SurfacePoint sp = rc_surface_point(&scene, ray, hit);
    uint traced = 0;
    const int classified =
        rc_ivg_visible_corners(&scene, &params, cell_planes, planes, &sp, &traced);
    const int3 base = rc_ivg_cell_base(&params, rc_ivg_grid_coordinates(&params, sp.position));
    int all_rays = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const float3 vertex = rc_ivg_corner_position(&params, base, corner);
        const float3 target = vertex + 0.01f * (sp.origin - vertex);
        if (!rc_occluded(&scene, sp.origin, target, false, target - sp.origin)) {
            all_rays |= 1 << corner;
        }
    }
    out[i] = (uint4)((uint)classified, (uint)all_rays, traced, 1u);
}
