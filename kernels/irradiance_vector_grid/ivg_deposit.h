// Photon deposition into the irradiance vector grid (Pacanowski et al., INRIA RR-6983, §3.3):
// the fixed-point amounts of voxel-face crossings, added with 64-bit atomics, and the face areas
// that normalise the sums. Only the grid's own kernels include this; readers of the grid need
// ivg_lookup.h alone.
#pragma once

#include "common/ivg_lookup.h"

// The fixed-point amount one crossing adds for colour channel value `flux` and component
// `incident` of the incident direction: flux * incident / cosine * units, where cosine is the
// travel direction's |cosine| to the face's normal (at least p->min_cosine). Photons cross a face
// in proportion to that cosine, so the sum over crossings per unit area estimates Arvo's irradiance
// vector, the integral of L(w) w over the hemisphere; the report's §3.3 formula omits the
// division, which makes a parallel beam's vector E cos(theta) w instead of E w. With the segment
// d and its length, incident / cosine = -d_k / max(|d_A|, min_cosine |d|): no normalisation, so the
// amounts are exact functions of the segment. Saturates at +-2^52.
RC_FUNC long rc_ivg_fixed(float flux, float minus_d_k, float denominator, float units,
                          int units_exponent) {
    RC_NO_FP_CONTRACT
    const float value = ldexp(flux * minus_d_k / denominator * units, units_exponent);
    const float limit = 4503599627370496.0f;
    if (!isfinite(value)) {
        return 0;
    }
    return (long)rint(clamp(value, -limit, limit));
}

// Adds the crossings of the segment from a to b (travel direction w = (b - a) / |b - a|) carrying
// `flux` to accum: at every crossing of a grid plane of axis A strictly after a (a segment leaving
// a surface that lies on a plane does not cross it) and up to b (a photon that ends on a surface
// lying on a plane has reached it), flux * (-w) / max(|w_A|, min_cosine) is added to the vector of
// the nearest vertex on that plane (rounding half up), for the direction -sign(w_A) A. Crossings
// outside the grid's faces are left out. Positions are computed per crossing from the plane's
// index, so they do not depend on the order of the walk. Returns the number of crossings.
RC_FUNC uint rc_ivg_deposit_segment(const IvgParams* p, float3 a, float3 b, float3 flux,
                                    RC_GLOBAL volatile long* accum) {
    RC_NO_FP_CONTRACT
    const float3 d = b - a;
    const float length_d = length(d);
    if (!(length_d > 0.0f) || !isfinite(length_d)) {
        return 0;
    }
    uint crossings = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const float da = rc_ivg_component(d, axis);
        if (da == 0.0f) {
            continue;
        }
        const float origin_a = rc_ivg_component(p->origin.xyz, axis);
        const float cell_a = rc_ivg_component(p->cell.xyz, axis);
        const int planes = rc_ivg_cells_along(p, axis);
        const float tolerance = 1.0e-4f * cell_a;
        // Plane n lies at origin_a + n cell_a; the segment covers [min, max] along the axis.
        const float a_a = rc_ivg_component(a, axis);
        const float b_a = rc_ivg_component(b, axis);
        const float low = (fmin(a_a, b_a) - origin_a) / cell_a;
        const float high = (fmax(a_a, b_a) - origin_a) / cell_a;
        const int first = max(0, (int)floor(low) - 1);
        const int last = min(planes, (int)ceil(high) + 1);
        const float denominator = fmax(fabs(da), p->min_cosine * length_d);
        const int direction = 2 * axis + (da < 0.0f ? 0 : 1);
        for (int n = first; n <= last; ++n) {
            const float plane = origin_a + (float)n * cell_a;
            // Distance along the axis from a to the plane, in the direction of travel.
            const float along = (plane - a_a) * (da > 0.0f ? 1.0f : -1.0f);
            if (!(along > tolerance) || !(along <= fabs(da) + tolerance)) {
                continue;
            }
            const float s = (plane - a_a) / da;
            int index[3];
            bool inside = true;
            for (int other = 0; other < 3; ++other) {
                if (other == axis) {
                    index[other] = n;
                    continue;
                }
                const float x = rc_ivg_component(a, other) + s * rc_ivg_component(d, other);
                const float g = (x - rc_ivg_component(p->origin.xyz, other)) /
                                rc_ivg_component(p->cell.xyz, other);
                const int count = rc_ivg_cells_along(p, other);
                const float slack = 1.0e-4f;
                if (!(g >= -slack) || !(g <= (float)count + slack)) {
                    inside = false;
                }
                index[other] = clamp((int)floor(g + 0.5f), 0, count);
            }
            if (!inside) {
                continue;
            }
            const int v = rc_ivg_vertex(p, index[0], index[1], index[2]);
            RC_GLOBAL volatile long* slot = accum + (size_t)(v * 6 + direction) * 9;
            const float minus_d[3] = {-d.x, -d.y, -d.z};
            const float channel[3] = {flux.x, flux.y, flux.z};
            for (int c = 0; c < 3; ++c) {
                for (int k = 0; k < 3; ++k) {
                    const long amount = rc_ivg_fixed(channel[c], minus_d[k], denominator,
                                                     p->fixed_point_scale, p->fixed_point_exponent);
                    if (amount != 0) {
                        rc_atomic_add_long(slot + 3 * c + k, amount);
                    }
                }
            }
            ++crossings;
        }
    }
    return crossings;
}

// Area of the face cell around a vertex, perpendicular to `axis` (§3.3): the voxel face's area,
// halved for each other axis along which the vertex lies on the grid's boundary.
RC_FUNC float rc_ivg_face_area(const IvgParams* p, int axis, int i, int j, int k) {
    const int index[3] = {i, j, k};
    float area = 1.0f;
    for (int other = 0; other < 3; ++other) {
        if (other == axis) {
            continue;
        }
        area *= rc_ivg_component(p->cell.xyz, other);
        if (index[other] == 0 || index[other] == rc_ivg_cells_along(p, other)) {
            area *= 0.5f;
        }
    }
    return area;
}
