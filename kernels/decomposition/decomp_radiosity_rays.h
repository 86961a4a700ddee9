// The far field's rays with --decomp-source radiosity (the paper, §4: "Wherever these rays hit,
// we lookup the proxy global illumination"; §6: the coarse solution is the split triangles'
// radiosity B(t)): a cluster's ray finds the split triangle it hits (the scene triangle's split
// tree, shared::SplitNode) once, and its radiance B(t) / pi is read from the latest radiosity
// with no further ray.
#pragma once

#include "common/light.h"
#include "common/scene_data.h"
#include "decomposition/decomp_far.h"

// The split triangle that point x of scene triangle `primitive` lies on: its split tree descended
// from roots[primitive] (host twin: split_triangle_of in triangle_split.h).
RC_FUNC int rc_decomp_split_triangle_of(RC_GLOBAL const SplitNode* nodes,
                                        RC_GLOBAL const uint* roots, uint primitive, float3 x) {
    RC_GLOBAL const SplitNode* node = nodes + roots[primitive];
    while (node->children >= 0) {
        const float side = dot(node->plane.xyz, x) + node->plane.w;
        node = nodes + node->children + (side >= 0.0f ? 0 : 1);
    }
    return node->triangle;
}

// Ray r of a cluster (rc_decomp_cluster_ray) traced to its closest hit, returned; *out started
// from it (direction, offset from the cluster's centre, no radiance, no split triangle), *ray and
// *rng left for the caller. *rays counts the ray.
RC_FUNC Hit rc_decomp_cluster_ray_hit(const DecompParams* params, const SceneData* scene,
                                      const DecompCluster* cluster, RC_GLOBAL const uint* members,
                                      RC_GLOBAL const GBufferSample* gbuffer, uint r,
                                      RngStream* rng, Ray* ray, ClusterRay* out, uint* rays) {
    *ray = rc_decomp_cluster_ray(params, cluster, members, gbuffer, r, rng);
    out->direction = (float4)(ray->direction.xyz, 0.0f);
    out->offset = (float4)(ray->origin.xyz - cluster->centre.xyz, 0.0f);
    out->radiance = (float4)(0.0f);
    out->split_triangle = -1;
    out->pad1 = 0;
    *rays += 1;
    return rc_trace_closest(scene->nodes, scene->triangles, *ray);
}

// Ray r of a cluster, traced to its closest hit only: whether it enters the fit and whether its
// hit lies inside the cluster's bounding sphere (as rc_decomp_trace_cluster_ray), the split
// triangle whose front it hits (-1 for a miss or a back face), and as radiance only the emission
// it sees when the tests count it (rc_decomp_radiosity_ray adds B(t) / pi). *rays counts the rays
// traced.
RC_FUNC ClusterRay rc_decomp_trace_cluster_hit(
    const DecompParams* params, const SceneData* scene, RC_GLOBAL const SplitNode* nodes,
    RC_GLOBAL const uint* roots, const DecompCluster* cluster, RC_GLOBAL const uint* members,
    RC_GLOBAL const GBufferSample* gbuffer, uint r, uint* rays) {
    RngStream rng;
    Ray ray;
    ClusterRay out;
    const Hit hit = rc_decomp_cluster_ray_hit(params, scene, cluster, members, gbuffer, r, &rng,
                                              &ray, &out, rays);
    const bool missed = hit.primitive == RC_NO_HIT;
    out.kept = rc_decomp_is_distant(missed ? INFINITY : hit.t, params->alpha) ? 1 : 0;
    out.inside = 0;
    if (missed) {
        if (out.kept != 0 && scene->environment >= 0 && params->count_emission != 0) {
            out.radiance = (float4)(rc_environment_light(scene, ray.direction.xyz), 0.0f);
        }
        return out;
    }
    const SurfacePoint sp = rc_surface_point(scene, ray, hit);
    out.inside = rc_decomp_inside_cluster(cluster, sp.position) ? 1 : 0;
    if (out.kept == 0 || !sp.front) {
        return out;
    }
    out.split_triangle = rc_decomp_split_triangle_of(nodes, roots, hit.primitive, sp.position);
    if (sp.light >= 0 && params->count_emission != 0) {
        out.radiance = (float4)(scene->lights[sp.light].radiance.xyz, 0.0f);
    }
    return out;
}

// A kept ray's radiance from the split triangles' radiosity: what `traced` brought back (emission
// the tests count) plus B(t) / pi = radiance[t] of the split triangle t it hit.
RC_FUNC ClusterRay rc_decomp_radiosity_ray(ClusterRay traced, RC_GLOBAL const float4* radiance) {
    if (traced.kept != 0 && traced.split_triangle >= 0) {
        traced.radiance.xyz += radiance[traced.split_triangle].xyz;
    }
    return traced;
}
