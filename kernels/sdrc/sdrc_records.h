// SDRC's records on the device (SDRC §4.3, §4.6; DESIGN.md §6.5): the N directions a new record
// draws by importance sampling its site's specular lobe, the L-tree node each traced direction
// becomes, and the record's radius from its hit distances and the finite-difference gradient of
// its outgoing radiance.
#pragma once

#include "caching/glossy_query.h"
#include "sdrc/sdrc_lobe.h"
#include "shared/sdrc.h"

// The key of the records' direction streams.
RC_FUNC void rc_sdrc_record_key(const SdrcParams* params, uint* key_lo, uint* key_hi) {
    *key_lo = params->seed_lo ^ RC_SDRC_RECORD_DOMAIN;
    *key_hi = params->seed_hi;
}

// The frame of a record's L-tree: its shading normal's (rc_ic_record_frame), the same on every
// side that maps directions into it.
RC_FUNC Frame rc_sdrc_record_frame(float3 normal) { return rc_ic_record_frame(normal); }

// A world direction as a node of the L-tree of a record with that frame (paraboloid map,
// quantised) carrying radiance l; an empty node for a direction below the frame's plane.
RC_FUNC LTreeNode rc_sdrc_node(const Frame* frame, float3 direction, float3 l) {
    LTreeNode node;
    const float3 d = rc_to_local(frame, direction);
    if (!(d.z > 0.0f)) {
        node.radiance = 0u;
        node.position = RC_LTREE_EMPTY;
        return node;
    }
    float u, v;
    rc_paraboloid_map(d.x, d.y, d.z, &u, &v);
    node.radiance = rc_rgbe_encode(l.x, l.y, l.z);
    node.position = rc_ltree_quantise(u) | rc_ltree_quantise(v) << 8;
    return node;
}

// Direction k of record `record` at `site` (stream record, index k): the site's specular lobe
// sampled at its w_o (SDRC §4.3: "random directions using BRDF importance sampling"), in world
// space with its weight f_s cos / (rho_s p). False where the sample leaves below the shading or
// the geometric surface (no ray).
RC_FUNC bool rc_sdrc_record_direction(const SdrcParams* params, RC_GLOBAL const Material* materials,
                                      const RcQuery* site, uint record, uint k, float3* direction,
                                      float* weight) {
    uint key_lo, key_hi;
    rc_sdrc_record_key(params, &key_lo, &key_hi);
    float u1, u2, pdf;
    rc_sdrc_direction_numbers(key_lo, key_hi, record, k, &u1, &u2);
    const Material material = materials[site->material];
    float3 wi;
    if (!rc_sdrc_lobe_sample(&material, site->outgoing.xyz, u1, u2, &wi, &pdf, weight)) {
        return false;
    }
    const Frame frame = rc_query_frame(site);
    *direction = rc_from_local(&frame, wi);
    return dot(*direction, site->geometric_normal.xyz) > 0.0f;
}

// A record's radius inputs from its N samples (radiance rgb and hit distance w each; SDRC §4.6):
// x the harmonic mean of the hit distances (a direction with no ray or no hit is infinitely
// far), y their minimum, z the gradient limit L_o / |grad L_o| (infinite without a gradient), w
// the outgoing luminance L_o. The gradient by finite differences: each sample's ray origin moved
// by delta along the frame's t and b, its direction turned to the same hit, the lobe re-evaluated
// with the sample's original density; the incoming radiance is held fixed (SDRC §4.6).
RC_FUNC float4 rc_sdrc_record_radius(const SdrcParams* params, RC_GLOBAL const Material* materials,
                                     const RcQuery* site, uint record,
                                     RC_GLOBAL const float4* samples) {
    const int n = params->samples;
    float inverse = 0.0f;
    float nearest = INFINITY;
    for (int k = 0; k < n; ++k) {
        inverse += 1.0f / samples[k].w;
        nearest = fmin(nearest, samples[k].w);
    }
    const float harmonic = inverse > 0.0f ? (float)n / inverse : INFINITY;
    const float delta = isfinite(harmonic) ? 1e-2f * harmonic : 0.0f;
    const Material material = materials[site->material];
    const Frame frame = rc_query_frame(site);
    const float3 wo = site->outgoing.xyz;
    float outgoing = 0.0f, moved_x = 0.0f,
          moved_y = 0.0f;  // N times L_o at p, p + delta t, p + delta b
    for (int k = 0; k < n; ++k) {
        float3 direction;
        float weight;
        if (!rc_sdrc_record_direction(params, materials, site, record, (uint)k, &direction,
                                      &weight)) {
            continue;
        }
        const float l = rc_luminance(samples[k].xyz);
        outgoing += l * weight;
        if (!(delta > 0.0f) || !isfinite(samples[k].w)) {
            moved_x += l * weight;  // no hit: the direction does not turn
            moved_y += l * weight;
            continue;
        }
        const float3 wi = rc_to_local(&frame, direction);
        const float pdf = weight > 0.0f ? rc_sdrc_lobe_value(&material, wo, wi) / weight : 0.0f;
        const float3 hit = direction * samples[k].w;  // relative to the site
        const float3 towards_x = rc_to_local(&frame, normalize(hit - delta * frame.t));
        const float3 towards_y = rc_to_local(&frame, normalize(hit - delta * frame.b));
        if (pdf > 0.0f) {
            moved_x += l * rc_sdrc_lobe_value(&material, wo, towards_x) / pdf;
            moved_y += l * rc_sdrc_lobe_value(&material, wo, towards_y) / pdf;
        }
    }
    float limit = INFINITY;
    if (delta > 0.0f && outgoing > 0.0f) {
        const float gx = (moved_x - outgoing) / delta;
        const float gy = (moved_y - outgoing) / delta;
        const float gradient = sqrt(gx * gx + gy * gy);
        limit = gradient > 0.0f ? outgoing / gradient : INFINITY;
    }
    return (float4)(harmonic, nearest, limit, outgoing / (float)n);
}
