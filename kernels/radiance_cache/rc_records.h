// Radiance caching's records on the device (DESIGN.md §6.4; Křivánek et al., "Radiance Caching
// for Efficient Global Illumination Computation", TVCG 2005, "TVCG" below): the camera samples it
// serves, the hemisphere rays of a record, its projection with gradients, and the interpolation
// of records at a camera sample.
#pragma once

#include "caching/glossy_query.h"
#include "caching/pipeline_shading.h"
#include "common/record_weight.h"
#include "radiance_cache/rc_brdf_table.h"
#include "radiance_cache/rc_gradients.h"
#include "radiance_cache/rc_interpolation.h"
#include "radiance_cache/rc_rotation.h"
#include "shared/radiance_cache.h"

// The key of the records' random streams (rc_grid_stratum_direction's key).
RC_FUNC void rc_record_key(const RcParams* params, uint* key_lo, uint* key_hi) {
    *key_lo = params->seed_lo ^ RC_RC_RNG_DOMAIN;
    *key_hi = params->seed_hi;
}

// The camera sample s of a pixel as radiance caching sees it (rc_glossy_camera_query) with the
// order its material's BRDF table gives for w_o (TVCG §4.1: the material's order, or 0 where
// w_o's lobe needs more than n_max, Monte Carlo; -1 where there is no specular lobe to cache, or
// no bounce left for indirect light).
RC_FUNC RcQuery rc_camera_query(const SceneData* scene, const IcParams* params,
                                const CameraParams* camera, RC_GLOBAL const BrdfTableInfo* infos,
                                RC_GLOBAL const int* orders, uint pixel, uint s) {
    bool glossy;
    RcQuery q = rc_glossy_camera_query(scene, params, camera, pixel, s, &glossy);
    if (!glossy) {
        return q;
    }
    const BrdfTableInfo info = infos[q.material];
    const float3 wo = q.outgoing.xyz;
    // The material's order where the table represents w_o's lobe (TVCG §4.1-4.2: one order
    // per material, the lowest whose error stays below the bound over its represented
    // directions).
    const bool represented =
        info.first_texel >= 0 && wo.z > 0.0f && rc_brdf_table_order(orders, &info, wo) > 0;
    q.order = represented ? info.order : 0;
    return q;
}

// The direction of cell `cell` of record `record` in world space: rc_grid_stratum_direction in
// the record's frame (rc_ic_record_frame of its shading normal) (TVCG §4.2, eq. 4: stratified
// uniform hemisphere sampling).
RC_FUNC float3 rc_record_cell_direction(const RcParams* params, uint record, int cell,
                                        float3 normal) {
    uint key_lo, key_hi;
    rc_record_key(params, &key_lo, &key_hi);
    const Frame frame = rc_ic_record_frame(normal);
    return rc_from_local(&frame, rc_grid_stratum_direction(key_lo, key_hi, record, cell,
                                                           params->strata_m, params->strata_n));
}

// The random stream of cell `cell` of record `record` past the jitter words (the light the
// cell's ray brings back draws from it).
RC_FUNC RngStream rc_record_cell_stream(const RcParams* params, uint record, int cell) {
    uint key_lo, key_hi;
    rc_record_key(params, &key_lo, &key_hi);
    RngStream rng = rc_rng_stream(key_lo, key_hi, record, (uint)cell);
    rc_rng_next_float(&rng);
    rc_rng_next_float(&rng);
    return rng;
}

// Harmonic mean and minimum of a record's hit distances (a miss is infinitely far; the harmonic
// mean of no hit is infinite): the distances the record's radius starts from (TVCG §4.4).
RC_FUNC float2 rc_record_distances(RC_GLOBAL const float4* cells, int count) {
    float inverse = 0.0f;
    float nearest = INFINITY;
    for (int c = 0; c < count; ++c) {
        inverse += 1.0f / cells[c].w;
        nearest = fmin(nearest, cells[c].w);
    }
    return (float2)(inverse > 0.0f ? (float)count / inverse : INFINITY, nearest);
}

// One covering record's reflection at query q (rc_record_reflection: TVCG §4.4 eq. 12 and §4.5
// eq. 13): its payload (9 params->order^2 floats: r, g, b, then r x, r y, g x, g y, b x, b y)
// truncated to `order` (at most params->order), displaced in the record's frame, against the
// BRDF vector `brdf` (q's frame, order^2 coefficients).
RC_FUNC float3 rc_covering_reflection(const RcParams* params, RC_GLOBAL const Record* record,
                                      RC_GLOBAL const float* payload, const RcQuery* q, int order,
                                      const Frame* query_frame, RC_GLOBAL const float* x90,
                                      const float* brdf) {
    const int stored = rc_sh_count(params->order);
    const int count = rc_sh_count(order);
    float c[3 * RC_SH_MAX_COEFFICIENTS];
    float g[6 * RC_SH_MAX_COEFFICIENTS];
    float rotated[RC_SH_MAX_COEFFICIENTS];
    for (int v = 0; v < 3; ++v) {
        for (int i = 0; i < count; ++i) {
            c[v * count + i] = payload[v * stored + i];
        }
    }
    for (int v = 0; v < 6; ++v) {
        for (int i = 0; i < count; ++i) {
            g[v * count + i] = payload[(3 + v) * stored + i];
        }
    }
    for (int i = 0; i < count; ++i) {
        rotated[i] = brdf[i];
    }
    const Frame frame = rc_ic_record_frame(record->normal.xyz);
    float rotation[9];
    rc_frame_rotation(&frame, query_frame, rotation);
    const float3 offset = q->position.xyz - record->position.xyz;
    return rc_record_reflection(c, g, order, dot(offset, frame.t), dot(offset, frame.b), rotation,
                                x90, rotated);
}
