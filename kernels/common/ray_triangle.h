// Watertight ray/triangle intersection: Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013. The ray is transformed so that it runs along +z from the
// origin (permutation kx, ky, kz and shear Sx, Sy, Sz, §3); the 2-D edge functions U, V, W then
// decide inside/outside exactly on shared edges and vertices, so no ray slips between triangles.
#pragma once

#include "shared/types.h"

// The per-ray part of the test.
typedef struct WatertightRay {
    float4 origin;  // xyz: ray origin
    uint4 permute;  // (kx, ky, kz, 3): kz is the dominant axis of the direction
    float shear_x, shear_y, shear_z;
    float permuted_origin_x, permuted_origin_y, permuted_origin_z;  // origin (kx, ky, kz)
} WatertightRay;

RC_FUNC WatertightRay rc_watertight_ray(float3 origin, float3 direction) {
    WatertightRay r;
    const float3 a = fabs(direction);
    // Dominant axis kz; kx, ky follow it cyclically and swap when d_kz < 0 to keep the winding.
    uint kz = (a.x >= a.y) ? ((a.x >= a.z) ? 0u : 2u) : ((a.y >= a.z) ? 1u : 2u);
    uint kx = (kz == 2u) ? 0u : kz + 1u;
    uint ky = (kx == 2u) ? 0u : kx + 1u;
    const float4 d = (float4)(direction, 0.0f);
    const float dz = (kz == 0u) ? d.x : ((kz == 1u) ? d.y : d.z);
    if (dz < 0.0f) {
        const uint swap = kx;
        kx = ky;
        ky = swap;
    }
    r.permute = (uint4)(kx, ky, kz, 3u);
    const float4 dp = rc_shuffle(d, r.permute);
    r.shear_x = dp.x / dp.z;
    r.shear_y = dp.y / dp.z;
    r.shear_z = 1.0f / dp.z;
    r.origin = (float4)(origin, 0.0f);
    const float4 o = rc_shuffle(r.origin, r.permute);
    r.permuted_origin_x = o.x;
    r.permuted_origin_y = o.y;
    r.permuted_origin_z = o.z;
    return r;
}

// Intersects the triangle (v0, v1, v2); on a hit with tmin < t <= tmax writes t and the
// barycentric coordinates (u, v) of v1 and v2. Both sides of the triangle are hit.
RC_FUNC bool rc_intersect_triangle(const WatertightRay* r, float4 v0, float4 v1, float4 v2,
                                   float tmin, float tmax, float* t, float* u, float* v) {
    // A shared edge must give exactly opposite edge functions in its two triangles; a fused
    // multiply-add would round the two products differently and open cracks.
    RC_NO_FP_CONTRACT
    // Vertices relative to the origin, permuted so that z is the dominant ray axis.
    const float4 a = rc_shuffle(v0 - r->origin, r->permute);
    const float4 b = rc_shuffle(v1 - r->origin, r->permute);
    const float4 c = rc_shuffle(v2 - r->origin, r->permute);
    // Shear so the ray runs along +z (the paper's eq. for Ax, Ay, ...).
    const float ax = a.x - r->shear_x * a.z;
    const float ay = a.y - r->shear_y * a.z;
    const float bx = b.x - r->shear_x * b.z;
    const float by = b.y - r->shear_y * b.z;
    const float cx = c.x - r->shear_x * c.z;
    const float cy = c.y - r->shear_y * c.z;
    // Scaled barycentric coordinates: the 2-D edge functions.
    float e0 = cx * by - cy * bx;
    float e1 = ax * cy - ay * cx;
    float e2 = bx * ay - by * ax;
#ifdef RC_HAS_DOUBLE
    // An edge function that rounds to exactly zero is recomputed in double, which is exact for
    // products of floats, so the inside test of a ray through an edge is consistent (§3.2).
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
        e0 = (float)((double)cx * (double)by - (double)cy * (double)bx);
        e1 = (float)((double)ax * (double)cy - (double)ay * (double)cx);
        e2 = (float)((double)bx * (double)ay - (double)by * (double)ax);
    }
#endif
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) {
        return false;
    }
    const float det = e0 + e1 + e2;
    if (det == 0.0f) {
        return false;
    }
    // Scaled hit distance, compared against the interval without a division.
    const float scaled_t = r->shear_z * (e0 * a.z + e1 * b.z + e2 * c.z);
    const float det_abs = fabs(det);
    const float signed_t = (det < 0.0f) ? -scaled_t : scaled_t;
    if (!(signed_t > tmin * det_abs && signed_t <= tmax * det_abs)) {
        return false;
    }
    const float inv_det = 1.0f / det;
    *t = scaled_t * inv_det;
    *u = e1 * inv_det;
    *v = e2 * inv_det;
    return true;
}

// The same test of the four triangles of a packet at once, lane by lane the very operations of
// rc_intersect_triangle (so the same t, u and v, bit for bit); returns the lanes hit in
// (tmin, tmax] as -1.
RC_FUNC int4 rc_intersect_triangle_packet(const WatertightRay* r,
                                          RC_GLOBAL const TrianglePacket* packet, float tmin,
                                          float tmax, float4* t, float4* u, float4* v) {
    RC_NO_FP_CONTRACT
    const uint kx = r->permute.x;
    const uint ky = r->permute.y;
    const uint kz = r->permute.z;
    // Vertices relative to the origin, permuted so that z is the dominant ray axis.
    const float4 az = packet->v0[kz] - r->permuted_origin_z;
    const float4 bz = packet->v1[kz] - r->permuted_origin_z;
    const float4 cz = packet->v2[kz] - r->permuted_origin_z;
    const float4 ax = (packet->v0[kx] - r->permuted_origin_x) - r->shear_x * az;
    const float4 ay = (packet->v0[ky] - r->permuted_origin_y) - r->shear_y * az;
    const float4 bx = (packet->v1[kx] - r->permuted_origin_x) - r->shear_x * bz;
    const float4 by = (packet->v1[ky] - r->permuted_origin_y) - r->shear_y * bz;
    const float4 cx = (packet->v2[kx] - r->permuted_origin_x) - r->shear_x * cz;
    const float4 cy = (packet->v2[ky] - r->permuted_origin_y) - r->shear_y * cz;
    float4 e0 = cx * by - cy * bx;
    float4 e1 = ax * cy - ay * cx;
    float4 e2 = bx * ay - by * ax;
#ifdef RC_HAS_DOUBLE
    const int4 zero = e0 == 0.0f || e1 == 0.0f || e2 == 0.0f;
    if (any(zero)) {
        const double4 dax = convert_double4(ax), day = convert_double4(ay);
        const double4 dbx = convert_double4(bx), dby = convert_double4(by);
        const double4 dcx = convert_double4(cx), dcy = convert_double4(cy);
        e0 = select(e0, convert_float4(dcx * dby - dcy * dbx), zero);
        e1 = select(e1, convert_float4(dax * dcy - day * dcx), zero);
        e2 = select(e2, convert_float4(dbx * day - dby * dax), zero);
    }
#endif
    const int4 mixed_signs =
        (e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f);
    const float4 det = e0 + e1 + e2;
    const float4 scaled_t = r->shear_z * (e0 * az + e1 * bz + e2 * cz);
    const float4 det_abs = fabs(det);
    const float4 signed_t = select(scaled_t, -scaled_t, det < 0.0f);
    const int4 hit =
        !mixed_signs && det != 0.0f && signed_t > tmin * det_abs && signed_t <= tmax * det_abs;
    if (!any(hit)) {
        return hit;
    }
    const float4 inv_det = 1.0f / det;
    *t = scaled_t * inv_det;
    *u = e1 * inv_det;
    *v = e2 * inv_det;
    return hit;
}
