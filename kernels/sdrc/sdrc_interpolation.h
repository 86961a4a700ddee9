// SDRC's interpolation at a camera sample (SDRC §4.4-4.5, Algorithm 1; DESIGN.md §6.5): M
// directions drawn from the sample's specular lobe, each looked up by a range query in the L-trees
// of the records that cover the sample, the found radiance samples weighted by the product of
// the spatial and the directional weight; a direction no L-tree answers becomes a miss, traced
// later from a contributing record and inserted into its L-tree.
#pragma once

#include "common/record_weight.h"
#include "sdrc/ltree.h"
#include "sdrc/sdrc_records.h"

// The records and their L-trees as the interpolation reads them.
typedef struct SdrcCache {
    RecordGrid grid;
    RC_GLOBAL const int* cell_start;
    RC_GLOBAL const int* cell_records;
    RC_GLOBAL const Record* records;
    RC_GLOBAL const RcQuery* sites;  // where each record was made
    RC_GLOBAL const SdrcTree* trees;
    RC_GLOBAL const LTreeNode* nodes;
} SdrcCache;

// The query radius in D of a direction drawn with density pdf (SDRC §4.4):
//   r_d = min(r_max, sqrt(1 / (2 pi M p))),
// M the directions a pixel draws (params->pixel_interp: the camera samples of a pixel share its
// shading point up to a pixel's footprint and draw M directions each).
RC_FUNC float rc_sdrc_query_radius(const SdrcParams* params, float pdf) {
    return fmin(params->max_radius, sqrt(1.0f / (2.0f * RC_PI * params->pixel_interp * pdf)));
}

// The interpolated incoming radiance along world direction w at query q (SDRC §4.4):
//   L~ = sum_i sum_k w_s,i w_d,ik L_ik / sum_i sum_k w_s,i w_d,ik
// over the records i covering q whose hemisphere holds w, into *radiance; false when no sample
// was found. *record: one of those records above whose geometric plane w leaves, chosen
// uniformly by reservoir sampling with rng (SDRC §4.4: "selected randomly from among the
// contributing L-trees for which w is above their tangent plane"), -1 when there is none.
// *range_queries counts the L-trees queried.
RC_FUNC bool rc_sdrc_lookup(const SdrcParams* params, const SdrcCache* cache, const RcQuery* q,
                            int cell, float3 w, float radius, RngStream* rng, float3* radiance,
                            int* record, uint* range_queries) {
    float3 sum = (float3)(0.0f);
    float total = 0.0f;
    int eligible = 0;
    *record = -1;
    for (int k = cache->cell_start[cell]; k < cache->cell_start[cell + 1]; ++k) {
        const int i = cache->cell_records[k];
        const float ws = rc_record_weight(cache->records + i, q->position.xyz, q->normal.xyz,
                                          params->accuracy, params->max_weight);
        if (ws <= 0.0f) {
            continue;
        }
        const Frame frame = rc_sdrc_record_frame(cache->records[i].normal.xyz);
        const float3 d = rc_to_local(&frame, w);
        if (!(d.z > 0.0f)) {
            continue;
        }
        if (dot(w, cache->sites[i].geometric_normal.xyz) > 0.0f) {
            ++eligible;
            if (rc_rng_next_float(rng) * (float)eligible < 1.0f) {
                *record = i;
            }
        }
        float u, v;
        rc_paraboloid_map(d.x, d.y, d.z, &u, &v);
        LTreeFound found;
        found.radiance = (float3)(0.0f);
        found.weight = 0.0f;
        found.count = 0u;
        rc_ltree_query(cache->nodes, cache->trees[i], u, v, radius, &found, 0, 0u);
        *range_queries += 1u;
        sum += ws * found.radiance;
        total += ws * found.weight;
    }
    *radiance = total > 0.0f ? sum / total : (float3)(0.0f);
    return total > 0.0f;
}

// The M directions of camera sample `sample` (query q, covered by the cache): sum over the
// answered ones of L~ f_s cos / (rho_s p) (eq. 3 before the 1/M), returned; misses[j] for each
// direction j: record -2 when it needs nothing more (answered, or zero weight), else the miss to
// trace. *answered counts the directions answered from the cache, *range_queries the L-trees
// queried.
RC_FUNC float3 rc_sdrc_interpolate(const SdrcParams* params, RC_GLOBAL const Material* materials,
                                   const SdrcCache* cache, const RcQuery* q, uint sample,
                                   RC_GLOBAL SdrcMiss* misses, uint* answered,
                                   uint* range_queries) {
    float3 sum = (float3)(0.0f);
    *answered = 0u;
    *range_queries = 0u;
    const int cell = rc_ic_grid_cell(&cache->grid, q->position.xyz);
    const Material material = materials[q->material];
    const Frame frame = rc_query_frame(q);
    for (int j = 0; j < params->interp; ++j) {
        SdrcMiss miss;
        miss.direction = (float4)(0.0f);
        miss.sample = sample;
        miss.index = (uint)j;
        miss.record = -2;
        miss.pad0 = 0u;
        RngStream rng =
            rc_rng_stream(params->seed_lo ^ RC_SDRC_QUERY_DOMAIN, params->seed_hi, sample, (uint)j);
        const float u1 = rc_rng_next_float(&rng);
        const float u2 = rc_rng_next_float(&rng);
        float3 wi;
        float pdf, weight;
        if (cell >= 0 &&
            rc_sdrc_lobe_sample(&material, q->outgoing.xyz, u1, u2, &wi, &pdf, &weight)) {
            const float3 w = rc_from_local(&frame, wi);
            if (dot(w, q->geometric_normal.xyz) > 0.0f) {
                float3 radiance;
                int record;
                if (rc_sdrc_lookup(params, cache, q, cell, w, rc_sdrc_query_radius(params, pdf),
                                   &rng, &radiance, &record, range_queries)) {
                    sum += weight * radiance;
                    *answered += 1u;
                } else {
                    miss.direction = (float4)(w, weight);
                    miss.record = record;
                }
            }
        }
        misses[j] = miss;
    }
    return sum;
}
