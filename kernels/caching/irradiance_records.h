// Irradiance caching on the device (DESIGN.md §6.2): the hemisphere sampling of a record and its
// gradients, and the weighted interpolation of records at a shading point.
#pragma once

#include "common/math.h"
#include "common/record_weight.h"
#include "common/sampling.h"
#include "shared/rng.h"
#include "shared/types.h"

// The random stream of cell `cell` of record `record` of cache level params->level (0: the
// records the camera samples read). Its words 0 and 1 are the cell's jitter (zeta, xi), so the
// reduction and the deeper levels' placement regenerate the sampled directions.
RC_FUNC uint rc_ic_level_key(const IcParams* params) {
    return params->seed_hi ^ ((uint)params->level * 0x9e3779b9u);
}

RC_FUNC RngStream rc_ic_cell_stream(const IcParams* params, uint record, uint cell) {
    return rc_rng_stream(params->seed_lo ^ RC_IC_RNG_DOMAIN, rc_ic_level_key(params), record, cell);
}

RC_FUNC void rc_ic_cell_jitter(const IcParams* params, uint record, uint cell, float* zeta,
                               float* xi) {
    const uint lo = params->seed_lo ^ RC_IC_RNG_DOMAIN;
    const uint hi = rc_ic_level_key(params);
    *zeta = rc_uint_to_unit_float(rc_rng_word(lo, hi, record, cell, 0u));
    *xi = rc_uint_to_unit_float(rc_rng_word(lo, hi, record, cell, 1u));
}

// Stratified cosine-weighted direction of cell (j, k) of an M x N division (Ward, Rubinstein and
// Clear 1988; course "Irradiance Computation"): theta = asin(sqrt((j + zeta) / M)),
// phi = 2 pi (k + xi) / N, in the frame whose z axis is the record normal.
RC_FUNC float3 rc_ic_cell_direction(int j, int k, int m, int n, float zeta, float xi) {
    const float sin2 = ((float)j + zeta) / (float)m;
    const float sin_theta = sqrt(sin2);
    const float cos_theta = sqrt(fmax(0.0f, 1.0f - sin2));
    const float phi = 2.0f * RC_PI * ((float)k + xi) / (float)n;
    return (float3)(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

// The record frame: Duff et al.'s basis completing the normal.
RC_FUNC Frame rc_ic_record_frame(float3 n) {
    Frame f;
    f.n = n;
    rc_orthonormal_basis(n, &f.t, &f.b);
    return f;
}

// Results of the hemisphere sampling of one record.
typedef struct RecordEstimate {
    float3 irradiance;
    float3 rotation[3];     // per channel
    float3 translation[3];  // per channel
    float harmonic_distance;
    float min_distance;
    float3 occluder;  // tangent-plane offset of the nearest hit (zero: none to the side)
} RecordEstimate;

// Irradiance, gradients and distances from the M x N cell samples (L.rgb, hit distance) of a
// record with normal n. Irradiance: E = pi / (M N) sum L (course "Irradiance Computation").
// Rotational gradient (Ward and Heckbert 1992, course "Rotational Gradient Formula"):
// pi / (M N) sum_k v_k sum_j tan(theta_j) L_jk, theta_j the polar angle at the stratum's centre,
// v_k = n x u_k the tangent direction a quarter turn past the stratum's azimuth. (The course
// writes -tan with v_k a quarter turn the other way; the sign here is the one for which
// (n_i x n) . grad_r is the change of E when n_i turns to n: dE = (omega x n) . integral of
// L w dw = omega . (n x integral of L w dw).)
// Translational gradient: the occlusion-aware irradiance variant of Krivanek et al., "Improved
// Radiance Gradient Computation" (2005), §3, last formula:
//   sum_k [ u_k 2 pi / N sum_{j>=1} cos(theta_jk) cos(theta_j-) sin(theta_j-)
//                                   / min(r_jk, r_j-1,k) (L_jk - L_j-1,k)
//         + v_k- sum_j cos(theta_jk) (cos(theta_j-) - cos(theta_j+))
//                      / (sin(theta_jk) min(r_jk, r_j,k-1)) (L_jk - L_j,k-1) ],
// u_k the tangent direction at the stratum's centre azimuth, v_k- the direction perpendicular to
// the stratum's leading azimuthal wall. Distances: harmonic mean and minimum of the hit
// distances (a miss is infinitely far).
RC_FUNC RecordEstimate rc_ic_reduce(const IcParams* params, uint record, float3 n,
                                    RC_GLOBAL const float4* cells) {
    const int m = params->strata_m;
    const int nn = params->strata_n;
    const Frame frame = rc_ic_record_frame(n);
    RecordEstimate e;
    float3 sum = (float3)(0.0f);
    float3 rotation[3] = {(float3)(0.0f), (float3)(0.0f), (float3)(0.0f)};
    float3 translation[3] = {(float3)(0.0f), (float3)(0.0f), (float3)(0.0f)};
    float inverse_distances = 0.0f;
    float min_distance = INFINITY;
    float3 nearest = (float3)(0.0f);  // local direction of the nearest hit
    for (int k = 0; k < nn; ++k) {
        const float phi_centre = 2.0f * RC_PI * ((float)k + 0.5f) / (float)nn;
        const float phi_wall = 2.0f * RC_PI * (float)k / (float)nn;
        const float3 u_k = cos(phi_centre) * frame.t + sin(phi_centre) * frame.b;
        const float3 v_k = -sin(phi_centre) * frame.t + cos(phi_centre) * frame.b;
        const float3 v_wall = -sin(phi_wall) * frame.t + cos(phi_wall) * frame.b;
        float3 rotation_k = (float3)(0.0f);
        float3 radial = (float3)(0.0f);
        float3 azimuthal = (float3)(0.0f);
        const int previous_k = (k == 0) ? nn - 1 : k - 1;
        for (int j = 0; j < m; ++j) {
            const uint cell = (uint)(j * nn + k);
            float zeta, xi;
            rc_ic_cell_jitter(params, record, cell, &zeta, &xi);
            const float4 sample = cells[cell];
            const float3 l = sample.xyz;
            const float r = sample.w;
            sum += l;
            inverse_distances += 1.0f / r;  // 0 for a miss (r = inf)
            const float sin2 = ((float)j + zeta) / (float)m;
            // The azimuthal walls' term divides by sin(theta): a stratum jittered onto the pole
            // (j = 0, zeta = 0, which the generator returns once in 2^24) is taken half a
            // generator step off it, so the gradient stays finite.
            const float sin_theta = sqrt(fmax(sin2, (0.5f / 16777216.0f) / (float)m));
            const float cos_theta = sqrt(fmax(0.0f, 1.0f - sin2));
            if (r < min_distance) {
                min_distance = r;
                nearest = rc_ic_cell_direction(j, k, m, nn, zeta, xi);
            }
            // Rotational: tan of the stratum's centre angle.
            const float centre2 = ((float)j + 0.5f) / (float)m;
            const float tan_centre = sqrt(centre2 / (1.0f - centre2));
            rotation_k += tan_centre * l;
            // Translational, radial walls (between strata j-1 and j of column k).
            const float sin2_minus = (float)j / (float)m;
            const float sin_minus = sqrt(sin2_minus);
            const float cos_minus = sqrt(1.0f - sin2_minus);
            const float cos_plus = sqrt(fmax(0.0f, 1.0f - ((float)j + 1.0f) / (float)m));
            if (j > 0) {
                const float4 below = cells[(uint)((j - 1) * nn + k)];
                radial += (cos_theta * cos_minus * sin_minus / fmin(r, below.w)) * (l - below.xyz);
            }
            // Translational, azimuthal walls (between columns k-1 and k of stratum j).
            const float4 before = cells[(uint)(j * nn + previous_k)];
            azimuthal += (cos_theta * (cos_minus - cos_plus) / (sin_theta * fmin(r, before.w))) *
                         (l - before.xyz);
        }
        const float radial_scale = 2.0f * RC_PI / (float)nn;
        for (int c = 0; c < 3; ++c) {
            const float rk = c == 0 ? rotation_k.x : (c == 1 ? rotation_k.y : rotation_k.z);
            const float rad = c == 0 ? radial.x : (c == 1 ? radial.y : radial.z);
            const float azi = c == 0 ? azimuthal.x : (c == 1 ? azimuthal.y : azimuthal.z);
            rotation[c] += rk * v_k;
            translation[c] += (radial_scale * rad) * u_k + azi * v_wall;
        }
    }
    const float scale = RC_PI / (float)(m * nn);
    e.irradiance = scale * sum;
    for (int c = 0; c < 3; ++c) {
        e.rotation[c] = scale * rotation[c];
        e.translation[c] = translation[c];
    }
    e.harmonic_distance = inverse_distances > 0.0f ? (float)(m * nn) / inverse_distances : INFINITY;
    e.min_distance = min_distance;
    // The nearest hit's offset along the tangent plane: points beyond it in that direction lie
    // past the nearest occluder (rc_ic_weight). Occluders within 45 degrees of the normal are
    // above the record rather than beside it and bound nothing.
    e.occluder = (float3)(0.0f);
    if (isfinite(min_distance) && nearest.z < 0.70710678f) {
        e.occluder = min_distance * (nearest.x * frame.t + nearest.y * frame.b);
    }
    return e;
}

// The weight of an irradiance record at point p with normal n: Ward's weight (rc_record_weight),
// and zero for points past the record's nearest occluder: p - p_i reaching beyond the plane
// through the nearest hit's tangent offset o, (p - p_i) . o > o . o. This keeps records from
// reaching through a thin wall to the coplanar surface on its other side (a ceiling running over
// it), where the raise to R_min would otherwise carry light.
RC_FUNC float rc_ic_weight(RC_GLOBAL const Record* record,
                           RC_GLOBAL const IrradiancePayload* payload, float3 p, float3 n,
                           float accuracy, float max_weight) {
    const float3 occluder = payload->occluder.xyz;
    if (dot(p - record->position.xyz, occluder) > dot(occluder, occluder)) {
        return 0.0f;
    }
    return rc_record_weight(record, p, n, accuracy, max_weight);
}

// A record's irradiance extrapolated to p, n by its gradients, never negative:
// E_i + (n_i x n) . grad_r E_i + (p - p_i) . grad_t E_i.
RC_FUNC float3 rc_ic_extrapolate(RC_GLOBAL const Record* record,
                                 RC_GLOBAL const IrradiancePayload* payload, float3 p, float3 n) {
    const float3 axis = cross(record->normal.xyz, n);
    const float3 offset = p - record->position.xyz;
    const float3 e =
        payload->irradiance.xyz +
        (float3)(dot(axis, payload->rotation_r.xyz), dot(axis, payload->rotation_g.xyz),
                 dot(axis, payload->rotation_b.xyz)) +
        (float3)(dot(offset, payload->translation_r.xyz), dot(offset, payload->translation_g.xyz),
                 dot(offset, payload->translation_b.xyz));
    return fmax(e, (float3)(0.0f));
}

// The grid cell of p, or -1 outside the grid.
RC_FUNC int rc_ic_grid_cell(const RecordGrid* grid, float3 p) {
    const float3 g = (p - grid->origin.xyz) * grid->inv_cell.xyz;
    if (!(g.x >= 0.0f && g.y >= 0.0f && g.z >= 0.0f)) {
        return -1;
    }
    const int x = (int)g.x;
    const int y = (int)g.y;
    const int z = (int)g.z;
    if (x >= grid->dims.x || y >= grid->dims.y || z >= grid->dims.z) {
        return -1;
    }
    return (z * grid->dims.y + y) * grid->dims.x + x;
}

// Weighted sum over the records list[begin .. end) at (p, n): rgb = sum w E', w = sum w, in list
// order (so the result is deterministic). Records of the list that do not cover (p, n) add
// nothing: any superset of the covering records in the same order gives the same sums.
RC_FUNC float4 rc_ic_weighted_sum(RC_GLOBAL const int* list, int begin, int end,
                                  RC_GLOBAL const Record* records,
                                  RC_GLOBAL const IrradiancePayload* payloads, float3 p, float3 n,
                                  float accuracy, float max_weight) {
    float4 sum = (float4)(0.0f);
    for (int i = begin; i < end; ++i) {
        RC_GLOBAL const Record* record = records + list[i];
        RC_GLOBAL const IrradiancePayload* payload = payloads + list[i];
        const float w = rc_ic_weight(record, payload, p, n, accuracy, max_weight);
        if (w > 0.0f) {
            sum += (float4)(w * rc_ic_extrapolate(record, payload, p, n), w);
        }
    }
    return sum;
}

// Whether any record of list[begin .. end) covers (p, n) with a positive weight: the support of
// the weighted sum (placement's test; it stops at the first).
RC_FUNC bool rc_ic_any_weight(RC_GLOBAL const int* list, int begin, int end,
                              RC_GLOBAL const Record* records,
                              RC_GLOBAL const IrradiancePayload* payloads, float3 p, float3 n,
                              float accuracy, float max_weight) {
    for (int i = begin; i < end; ++i) {
        if (rc_ic_weight(records + list[i], payloads + list[i], p, n, accuracy, max_weight) >
            0.0f) {
            return true;
        }
    }
    return false;
}

// The gather: the weighted sum at (p, n) over the records the world-space grid lists in p's
// cell (every record whose influence sphere touches the cell, in record order).
RC_FUNC float4 rc_ic_gather(const RecordGrid* grid, RC_GLOBAL const int* cell_start,
                            RC_GLOBAL const int* cell_records, RC_GLOBAL const Record* records,
                            RC_GLOBAL const IrradiancePayload* payloads, float3 p, float3 n,
                            float accuracy, float max_weight) {
    const int cell = rc_ic_grid_cell(grid, p);
    if (cell < 0) {
        return (float4)(0.0f);
    }
    return rc_ic_weighted_sum(cell_records, cell_start[cell], cell_start[cell + 1], records,
                              payloads, p, n, accuracy, max_weight);
}
