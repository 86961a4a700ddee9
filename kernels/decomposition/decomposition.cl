// Entry kernels of irradiance decomposition (host/methods/decomposition/decomposition.cpp; the
// paper: Arikan, Forsyth and O'Brien 2005): the G-buffer, the split triangles' radiosity, a
// cluster's far-field rays and their least-squares fit, the two terms of eq. 3 per camera sample,
// and the render pass. Built for the radiance source the rays read (the irradiance vector grid).
#include "common/kernel_range.h"
#include "decomposition/decomp_radiosity.h"
#include "decomposition/decomp_radiosity_rays.h"
#include "decomposition/decomp_shading.h"
#include "scene_arguments.h"
// The source after the method's own headers (see records/radiance_source.h).
#include "decomposition/decomp_source_rays.h"

// Entry i = pixel * spp + s: the first hit of that camera sample.
RC_KERNEL void decomp_gbuffer(uint begin, uint end, DecompParams params, CameraParams camera,
                              RC_SCENE_PARAMETERS, __global GBufferSample* gbuffer) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint spp = (uint)params.camera_spp;
    gbuffer[i] = rc_decomp_gbuffer_sample(&params, &scene, &camera, i / spp, i % spp);
}

// Item i: B(t) / pi of split triangle t = listed[i] from the coarse solution into radiance[t]
// (every triangle with --decomp-radiosity coarse; those no far-field sample covers when
// gathered). counters[0] counts the rays.
RC_KERNEL void decomp_radiosity(
    uint begin, uint end, DecompParams params, RC_SCENE_PARAMETERS,
    RC_RADIANCE_SOURCE_PARAMETERS __global const NearTriangle* near_triangles,
    __global const uint* listed, __global float4* radiance, __global uint* counters) {
    RC_RANGE_ITEM(i);
    const uint t = listed[i];
    const SceneData scene = RC_SCENE_DATA();
    const RadianceSource source = RC_RADIANCE_SOURCE_DATA();
    uint rays = 0;
    radiance[t] = (float4)(rc_decomp_triangle_radiance(&params, &scene, &source, near_triangles + t,
                                                       t, &rays),
                           0.0f);
    atomic_add(&counters[0], rays);
}

// Item t: what split triangle t sends back besides its diffuse lobe's indirect light, into
// direct[t], and its diffuse reflectance, into reflectance[t]. counters[0] counts the rays.
RC_KERNEL void decomp_radiosity_direct(uint begin, uint end, DecompParams params,
                                       RC_SCENE_PARAMETERS,
                                       __global const NearTriangle* near_triangles,
                                       __global float4* direct, __global float4* reflectance,
                                       __global uint* counters) {
    RC_RANGE_ITEM(t);
    const SceneData scene = RC_SCENE_DATA();
    uint rays = 0;
    float3 rho;
    direct[t] =
        (float4)(rc_decomp_triangle_direct(&params, &scene, near_triangles + t, t, &rho, &rays),
                 0.0f);
    reflectance[t] = (float4)(rho, 0.0f);
    atomic_add(&counters[0], rays);
}

// Item i: B(t) / pi of split triangle t = listed[i] path traced at `count` points
// (rc_decomp_triangle_traced) into radiance[t]. counters[0] counts the rays.
RC_KERNEL void decomp_radiosity_traced(uint begin, uint end, DecompParams params,
                                       RC_SCENE_PARAMETERS,
                                       __global const NearTriangle* near_triangles,
                                       __global const uint* listed, int count,
                                       __global float4* radiance, __global uint* counters) {
    RC_RANGE_ITEM(i);
    const uint t = listed[i];
    const SceneData scene = RC_SCENE_DATA();
    uint rays = 0;
    radiance[t] =
        (float4)(rc_decomp_triangle_traced(&params, &scene, near_triangles + t, t, count, &rays),
                 0.0f);
    atomic_add(&counters[0], rays);
}

// Item t: whether a far-field sample covers split triangle t (rc_decomp_triangle_covered; beyond
// every sample's reach counts as covered unless reach_needed) into covered[t].
RC_KERNEL void decomp_radiosity_coverage(uint begin, uint end, RecordGrid far_grid,
                                         __global const int* far_start,
                                         __global const int* far_samples,
                                         __global const Record* samples,
                                         __global const ShSample* coefficients,
                                         __global const NearTriangle* near_triangles,
                                         uint reach_needed, __global uint* covered) {
    RC_RANGE_ITEM(t);
    const FarField far = {far_grid, far_start, far_samples, samples, coefficients, 0};
    covered[t] = rc_decomp_triangle_covered(&far, near_triangles + t, reach_needed != 0);
}

// Item t: B(t) / pi of split triangle t gathered from the decomposition's two terms (the far
// field's gradients read with params.gradients) into radiance[t], the near triangles'
// radiosities read from `previous` (the last pass's) when with_near, I_N taken as 0 otherwise
// (the first pass); where covered[t] is 0, traced[t] (path traced) instead. counters[0] counts
// the rays.
RC_KERNEL void decomp_radiosity_gather(
    uint begin, uint end, DecompParams params, RC_SCENE_PARAMETERS, RecordGrid far_grid,
    __global const int* far_start, __global const int* far_samples, __global const Record* samples,
    __global const ShSample* coefficients, __global const ShGradient* gradients,
    RecordGrid near_grid, __global const int* near_start, __global const int* near_list,
    __global const NearTriangle* near_triangles, __global const float4* direct,
    __global const float4* reflectance, __global const uint* covered, __global const float4* traced,
    __global const float4* previous, uint with_near, __global float4* radiance,
    __global uint* counters) {
    RC_RANGE_ITEM(t);
    if (covered[t] == 0) {
        radiance[t] = traced[t];
        return;
    }
    const SceneData scene = RC_SCENE_DATA();
    const FarField far = {far_grid, far_start,    far_samples,
                          samples,  coefficients, params.gradients != 0 ? gradients : 0};
    const NearField near = rc_decomp_near_field(near_grid, near_start, near_list, near_triangles,
                                                previous, &params, &scene);
    uint rays = 0;
    radiance[t] =
        (float4)(rc_decomp_gathered_radiance(&far, &near, near_triangles + t, direct[t].xyz,
                                             reflectance[t].xyz, with_near != 0, &rays),
                 0.0f);
    atomic_add(&counters[0], rays);
}

// Item i: ray i % params.cluster_rays of batch cluster i / params.cluster_rays, into rays_out[i].
// counters[0] counts the rays traced.
RC_KERNEL void decomp_cluster_rays(
    uint begin, uint end, DecompParams params, RC_SCENE_PARAMETERS,
    RC_RADIANCE_SOURCE_PARAMETERS __global const DecompCluster* clusters,
    __global const uint* members, __global const GBufferSample* gbuffer,
    __global ClusterRay* rays_out, __global uint* counters) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const RadianceSource source = RC_RADIANCE_SOURCE_DATA();
    const uint per_cluster = (uint)params.cluster_rays;
    const DecompCluster cluster = clusters[i / per_cluster];
    uint rays = 0;
    rays_out[i] = rc_decomp_trace_cluster_ray(&params, &scene, &source, &cluster, members, gbuffer,
                                              i % per_cluster, &rays);
    atomic_add(&counters[0], rays);
}

// Item i: ray i % params.cluster_rays of batch cluster i / params.cluster_rays traced to its
// closest hit and the split triangle there (--decomp-source radiosity), into rays_out[i].
// counters[0] counts the rays traced.
RC_KERNEL void decomp_cluster_hits(uint begin, uint end, DecompParams params, RC_SCENE_PARAMETERS,
                                   __global const SplitNode* split_nodes,
                                   __global const uint* split_roots,
                                   __global const DecompCluster* clusters,
                                   __global const uint* members,
                                   __global const GBufferSample* gbuffer,
                                   __global ClusterRay* rays_out, __global uint* counters) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint per_cluster = (uint)params.cluster_rays;
    const DecompCluster cluster = clusters[i / per_cluster];
    uint rays = 0;
    rays_out[i] = rc_decomp_trace_cluster_hit(&params, &scene, split_nodes, split_roots, &cluster,
                                              members, gbuffer, i % per_cluster, &rays);
    atomic_add(&counters[0], rays);
}

// Item i: ray i with the radiance B(t) / pi of the split triangle it hit (--decomp-source
// radiosity) into rays_out[i].
RC_KERNEL void decomp_radiosity_rays(uint begin, uint end, __global const ClusterRay* traced,
                                     __global const float4* radiance,
                                     __global ClusterRay* rays_out) {
    RC_RANGE_ITEM(i);
    rays_out[i] = rc_decomp_radiosity_ray(traced[i], radiance);
}

// Item c: batch cluster c's least-squares fit of L_D* to its kept rays (in ray order; with
// params.gradients first order in the rays' origins) and its rays' counts.
RC_KERNEL void decomp_fit(uint begin, uint end, DecompParams params,
                          __global const ClusterRay* rays, __global ClusterFit* fits) {
    RC_RANGE_ITEM(c);
    fits[c] = rc_decomp_fit_cluster(&params, rays + (size_t)c * (uint)params.cluster_rays);
}

// Item i: I_D and I_N at G-buffer entry i (eq. 3, 4) into irradiance[i] (the far field's
// gradients read with params.gradients).
RC_KERNEL void decomp_irradiance(uint begin, uint end, DecompParams params, RC_SCENE_PARAMETERS,
                                 __global const GBufferSample* gbuffer, RecordGrid far_grid,
                                 __global const int* far_start, __global const int* far_samples,
                                 __global const Record* samples,
                                 __global const ShSample* coefficients,
                                 __global const ShGradient* gradients, RecordGrid near_grid,
                                 __global const int* near_start, __global const int* near_list,
                                 __global const NearTriangle* near_triangles,
                                 __global const float4* radiance,
                                 __global DecompIrradiance* irradiance) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const FarField far = {far_grid, far_start,    far_samples,
                          samples,  coefficients, params.gradients != 0 ? gradients : 0};
    const NearField near = rc_decomp_near_field(near_grid, near_start, near_list, near_triangles,
                                                radiance, &params, &scene);
    const GBufferSample g = gbuffer[i];
    irradiance[i] = rc_decomp_irradiance(&far, &near, &g);
}

// The render pass. Item = pixel: its camera samples shaded, the means written to film
// (RC_DECOMP_FILM_SLOTS per pixel). counters: [0] rays, [1] non-finite samples (dropped), [2] the
// first pixel that had one.
RC_KERNEL void decomp_shade(uint begin, uint end, DecompParams params, CameraParams camera,
                            RC_SCENE_PARAMETERS, __global const DecompIrradiance* irradiance,
                            __global float4* film, __global uint* counters) {
    RC_RANGE_ITEM(pixel);
    const SceneData scene = RC_SCENE_DATA();
    rc_decomp_shade_pixel(&params, &scene, &camera, irradiance, pixel, film, counters);
}
