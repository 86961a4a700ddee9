// The decomposition's rays that read the coarse global-illumination solution (the paper, §4:
// "Wherever these rays hit, we lookup the proxy global illumination"; here the source the program
// is built for, the irradiance vector grid): a cluster's far-field rays and the radiosity B(t) of
// the split triangles. Includes records/radiance_source.h: include this header after the
// program's other headers (see there).
#pragma once

#include "caching/radiance_source.h"
#include "decomposition/decomp_far.h"
#include "decomposition/decomp_radiosity.h"
#include "decomposition/decomp_radiosity_rays.h"

// Ray r of a cluster: its direction, whether it enters the fit, whether its hit lies inside the
// cluster's bounding sphere, and the radiance it brings back when kept (the source's: direct
// light at the hit by next-event estimation plus the grid's indirect light; the hit's own
// emission is direct light at the cluster's points, left to their next-event estimation unless
// the tests ask for it). Only kept rays read the source. *rays counts the rays traced.
RC_FUNC ClusterRay rc_decomp_trace_cluster_ray(const DecompParams* params, const SceneData* scene,
                                               const RadianceSource* source,
                                               const DecompCluster* cluster,
                                               RC_GLOBAL const uint* members,
                                               RC_GLOBAL const GBufferSample* gbuffer, uint r,
                                               uint* rays) {
    RngStream rng;
    Ray ray;
    ClusterRay out;
    const Hit hit = rc_decomp_cluster_ray_hit(params, scene, cluster, members, gbuffer, r, &rng,
                                              &ray, &out, rays);
    const float distance = hit.primitive == RC_NO_HIT ? INFINITY : hit.t;
    out.kept = rc_decomp_is_distant(distance, params->alpha) ? 1 : 0;
    out.inside =
        hit.primitive != RC_NO_HIT &&
                rc_decomp_inside_cluster(cluster, ray.origin.xyz + hit.t * ray.direction.xyz)
            ? 1
            : 0;
    if (out.kept != 0) {
        const SourceSample s =
            rc_source_radiance(scene, source, ray, &rng, params->count_emission != 0, 1,
                               params->max_depth, params->rr_depth);
        *rays += s.rays;
        out.radiance = (float4)(all(isfinite(s.radiance)) ? s.radiance : (float3)(0.0f), 0.0f);
    }
    return out;
}

// B(t) / pi of a split triangle's front from the coarse solution (--decomp-radiosity coarse; the
// paper, §6 pass 1: "we also compute the average radiosity value over all visible triangles"):
// the mean over params->radiosity_samples points of it (rc_decomp_triangle_ray) of the radiance a
// ray arriving along its normal brings back from the source (emission left out: light the
// emitters send to a shading point is its direct light). For a diffuse surface that radiance is
// its radiosity over pi; other lobes are read in the normal's mirror direction. *rays counts the
// rays traced.
RC_FUNC float3 rc_decomp_triangle_radiance(const DecompParams* params, const SceneData* scene,
                                           const RadianceSource* source,
                                           RC_GLOBAL const NearTriangle* triangle, uint t,
                                           uint* rays) {
    const int count = max(params->radiosity_samples, 1);
    float3 sum = (float3)(0.0f);
    for (int k = 0; k < count; ++k) {
        RngStream rng;
        const Ray ray = rc_decomp_triangle_ray(params, triangle, t, (uint)k, count, &rng);
        const SourceSample s =
            rc_source_radiance(scene, source, ray, &rng, params->count_emission != 0, 1,
                               params->max_depth, params->rr_depth);
        *rays += s.rays;
        if (all(isfinite(s.radiance))) {
            sum += s.radiance;
        }
    }
    return sum / (float)count;
}
