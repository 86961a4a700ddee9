// The far field (the paper, §4): the rays that sample a cluster's distant radiance L_D*, and the
// far-field samples interpolated at a shading point.
#pragma once

#include "common/math.h"
#include "common/sampling.h"
#include "decomposition/decomp_sh.h"
#include "decomposition/decomp_sh_gradient.h"
#include "shared/records.h"
#include "shared/rng.h"
#include "shared/types.h"

// The random stream of ray r of the cluster numbered `stream`.
RC_FUNC RngStream rc_decomp_cluster_stream(const DecompParams* params, uint stream, uint r) {
    return rc_rng_stream(params->seed_lo ^ RC_DECOMP_RNG_DOMAIN, params->seed_hi, stream, r);
}

// The radical inverse of i in base 2 (Van der Corput): the second coordinate of the Hammersley
// set that stratifies a cluster's ray directions.
RC_FUNC float rc_decomp_radical_inverse(uint i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
    i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
    i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
    return (float)(i >> 8) * (1.0f / 16777216.0f);
}

// Ray r of a cluster (§4.1: "shooting rays from random points in this set in random directions
// (in the incident hemisphere of the selected points)"; Fig. 3 b: the origins spread over the
// cluster's surfaces): from a member drawn at random, in a direction uniform in solid angle over
// its hemisphere, the cluster's rays stratified by a Hammersley set rotated at random per
// cluster (Cranley-Patterson) — uniform in solid angle, as a least-squares fit over the sphere
// wants. *rng continues ray r's stream.
RC_FUNC Ray rc_decomp_cluster_ray(const DecompParams* params, const DecompCluster* cluster,
                                  RC_GLOBAL const uint* members,
                                  RC_GLOBAL const GBufferSample* gbuffer, uint r, RngStream* rng) {
    RngStream shift = rc_decomp_cluster_stream(params, cluster->stream, 0xffffffffu);
    const float shift_u = rc_rng_next_float(&shift);
    const float shift_v = rc_rng_next_float(&shift);
    *rng = rc_decomp_cluster_stream(params, cluster->stream, r);
    const uint pick = min((uint)(rc_rng_next_float(rng) * (float)cluster->member_count),
                          cluster->member_count - 1u);
    const GBufferSample g = gbuffer[members[cluster->first_member + pick]];
    float u = ((float)r + 0.5f) / (float)params->cluster_rays + shift_u;
    float v = rc_decomp_radical_inverse(r) + shift_v;
    u -= floor(u);
    v -= floor(v);
    Ray ray;
    ray.origin = (float4)(g.origin.xyz, 0.0f);
    ray.direction = (float4)(rc_direction_about(g.normal.xyz, u, v), INFINITY);
    return ray;
}

// Whether a hit at `distance` along a ray enters the fit (§4: "Rays whose intersections are closer
// to P than alpha are discarded"): a miss (infinite distance) always does.
RC_FUNC bool rc_decomp_is_distant(float distance, float alpha) { return distance >= alpha; }

// Whether point x lies inside the cluster's bounding sphere (§4.1: "A single harmonic sample is
// not good enough ... if any of these rays intersects a surface within the bounding sphere").
RC_FUNC bool rc_decomp_inside_cluster(const DecompCluster* cluster, float3 x) {
    const float3 offset = x - cluster->centre.xyz;
    return dot(offset, offset) < cluster->test_radius * cluster->test_radius;
}

// The weight of a far-field sample at point p with unit normal n (§4.1: "a normalized distance
// weighted sum of the harmonic coefficients"): (1 - d / R)^2 within the sample's reach R =
// record.radius, 0 beyond (smooth at the border, so samples fade in and out without seams),
// times max(0, n . n_s)^2, n_s its cluster's mean normal (record.normal, shorter than 1 where the
// cluster mixes orientations): a sample fitted to the rays of one orientation's hemispheres
// extrapolates the others, so a point across a crease takes little of it.
RC_FUNC float rc_decomp_sample_weight(RC_GLOBAL const Record* sample, float3 p, float3 n) {
    const float d = length(p - sample->position.xyz);
    const float x = 1.0f - d / sample->radius;
    const float c = dot(n, sample->normal.xyz);
    return x > 0.0f && c > 0.0f ? x * x * c * c : 0.0f;
}

// The far-field samples' coefficients and, with --decomp-gradients on, their translational
// gradients (gradients is then non-null).
typedef struct FarCoefficients {
    RC_GLOBAL const ShSample* coefficients;
    RC_GLOBAL const ShGradient* gradients;
} FarCoefficients;

// Adds w times sample s's coefficients at p to *out: c + g . (p - x_s) with its gradients
// (Ward and Heckbert 1992's translational gradients; the fit's, rc_decomp_fit_with_gradients),
// c alone without.
RC_FUNC void rc_decomp_add_sample(const FarCoefficients* far, RC_GLOBAL const Record* samples,
                                  int s, float w, float3 p, ShSample* out) {
    const float3 offset = p - samples[s].position.xyz;
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        float4 c = far->coefficients[s].coefficients[i];
        if (far->gradients != 0) {
            RC_GLOBAL const ShGradient* g = far->gradients + s;
            c += offset.x * g->along_x[i] + offset.y * g->along_y[i] + offset.z * g->along_z[i];
        }
        out->coefficients[i] += w * c;
    }
}

// The far-field samples interpolated at p with unit normal n: the weighted mean of the
// coefficients (at p, with gradients) of those listed in list[begin .. end) (the record grid's
// cell of p), in list order. Where none has a positive weight, the listed one whose normal agrees
// best with n (the nearest, d / R, on ties) stands alone. Returns the samples with a positive
// weight; *out is all zero when the list is empty.
RC_FUNC uint rc_decomp_interpolate(RC_GLOBAL const int* list, int begin, int end,
                                   RC_GLOBAL const Record* samples, const FarCoefficients* far,
                                   float3 p, float3 n, ShSample* out) {
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        out->coefficients[i] = (float4)(0.0f);
    }
    float total = 0.0f;
    uint count = 0;
    int best = -1;
    float best_agreement = -INFINITY;
    float best_ratio = INFINITY;
    for (int k = begin; k < end; ++k) {
        const int s = list[k];
        const float agreement = dot(n, samples[s].normal.xyz);
        const float ratio = length(p - samples[s].position.xyz) / samples[s].radius;
        if (agreement > best_agreement || (agreement == best_agreement && ratio < best_ratio)) {
            best_agreement = agreement;
            best_ratio = ratio;
            best = s;
        }
        const float w = rc_decomp_sample_weight(samples + s, p, n);
        if (w <= 0.0f) {
            continue;
        }
        rc_decomp_add_sample(far, samples, s, w, p, out);
        total += w;
        ++count;
    }
    if (total > 0.0f) {
        for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
            out->coefficients[i] /= total;
        }
    } else if (best >= 0) {
        rc_decomp_add_sample(far, samples, best, 1.0f, p, out);
    }
    return count;
}

// A cluster's fit (§4): the least-squares coefficients of L_D* over its kept rays, in ray order
// ("when we compute the harmonic coefficients, we assume all the rays originate from the
// geometrical average of the origins of the rays", Fig. 3 b: the directions as traced), with
// params->gradients their translational gradients as well (rc_decomp_fit_with_gradients; all
// zero without), and the counts of kept rays and of rays that hit inside its bounding sphere.
RC_FUNC ClusterFit rc_decomp_fit_cluster(const DecompParams* params,
                                         RC_GLOBAL const ClusterRay* rays) {
    ClusterFit fit;
    if (params->gradients != 0) {
        rc_decomp_fit_with_gradients(params, rays, &fit);
    } else {
        ShNormalEquations e;
        rc_decomp_normal_equations_init(&e);
        for (int r = 0; r < params->cluster_rays; ++r) {
            if (rays[r].kept != 0) {
                rc_decomp_normal_equations_add(&e, rays[r].direction.xyz, rays[r].radiance.xyz);
            }
        }
        rc_decomp_solve(&e, params->ridge, &fit.sample);
        for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
            fit.gradient.along_x[i] = fit.gradient.along_y[i] = fit.gradient.along_z[i] =
                (float4)(0.0f);
        }
        fit.kept = e.kept;
    }
    uint inside = 0;
    for (int r = 0; r < params->cluster_rays; ++r) {
        inside += rays[r].inside != 0 ? 1u : 0u;
    }
    fit.inside = inside;
    fit.pad0 = fit.pad1 = 0;
    return fit;
}
