// Test kernels of irradiance decomposition (tests/decomposition/decomposition_test.cpp): the form
// factor, the distant term, the near correction, the hidden distant power and the split
// triangles' radiosity points, each on given inputs (the fit's own kernel, decomp_fit, is the
// method's).
#include "common/kernel_range.h"
#include "decomposition/decomp_far.h"
#include "decomposition/decomp_form_factor.h"
#include "decomposition/decomp_near.h"
#include "decomposition/decomp_radiosity.h"
#include "scene_arguments.h"
#include "shared/decomposition.h"

// Item i: FF of triangles[i] to the differential area at points[i] with unit normal normals[i].
RC_KERNEL void decomp_form_factors(uint begin, uint end, __global const float4* points,
                                   __global const float4* normals,
                                   __global const NearTriangle* triangles, __global float* out) {
    RC_RANGE_ITEM(i);
    out[i] = rc_decomp_form_factor(points[i].xyz, normals[i].xyz, triangles[i].v0.xyz,
                                   triangles[i].v1.xyz, triangles[i].v2.xyz);
}

// Item i: the distant power triangles[i] hides from points[i] with unit normal normals[i]
// (rc_decomp_hidden, L_D* of sample[0]) into hidden[i] (xyz; w: the triangle's FF).
RC_KERNEL void decomp_hidden_at(uint begin, uint end, __global const ShSample* sample,
                                __global const float4* points, __global const float4* normals,
                                __global const NearTriangle* triangles, __global float4* hidden) {
    RC_RANGE_ITEM(i);
    const ShSample far = sample[0];
    const float3 p = points[i].xyz;
    const float3 n = normals[i].xyz;
    const NearTriangle t = triangles[i];
    const float ff = rc_decomp_form_factor(p, n, t.v0.xyz, t.v1.xyz, t.v2.xyz);
    hidden[i] = (float4)(rc_decomp_hidden(&far, p, n, t.v0.xyz, t.v1.xyz, t.v2.xyz, ff), ff);
}

// Item q: I_D of sample samples[q] about the unit normal normals[q] into irradiance[q], and its
// L_D* in direction normals[q] into radiance[q].
RC_KERNEL void decomp_sh_terms(uint begin, uint end, __global const ShSample* samples,
                               __global const float4* normals, __global float4* irradiance,
                               __global float4* radiance) {
    RC_RANGE_ITEM(q);
    const ShSample s = samples[q];
    irradiance[q] = (float4)(rc_decomp_sh_irradiance(&s, normals[q].xyz), 0.0f);
    radiance[q] = (float4)(rc_decomp_sh_radiance(&s, normals[q].xyz), 0.0f);
}

// Item q: I_D about the unit normal normals[q] at points[q] of the single far-field sample (its
// coefficients, its gradients and its position centre[0]) as the interpolation reads it there
// (rc_decomp_interpolate's rc_decomp_add_sample) into irradiance[q].
RC_KERNEL void decomp_sh_irradiance_at(uint begin, uint end, __global const ShSample* coefficients,
                                       __global const ShGradient* gradients,
                                       __global const Record* centre, __global const float4* points,
                                       __global const float4* normals,
                                       __global float4* irradiance) {
    RC_RANGE_ITEM(q);
    const FarCoefficients far = {coefficients, gradients};
    ShSample s;
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        s.coefficients[i] = (float4)(0.0f);
    }
    rc_decomp_add_sample(&far, centre, 0, 1.0f, points[q].xyz, &s);
    irradiance[q] = (float4)(rc_decomp_sh_irradiance(&s, normals[q].xyz), 0.0f);
}

// Item q: I_N at points[q] with unit normal normals[q] (rc_decomp_near_correction, the paper's
// visibility heuristic) over the near triangles of the grid (near_grid.h) under params.near_set
// and params.alpha, with B(t) / pi = radiance[t] and no distant light (L_D* = 0), into
// correction[q] (xyz; w: the triangles summed).
RC_KERNEL void decomp_near_correction_at(
    uint begin, uint end, DecompParams params, RecordGrid near_grid, __global const int* near_start,
    __global const int* near_list, __global const NearTriangle* near_triangles,
    __global const float4* radiance, __global const float4* points, __global const float4* normals,
    __global float4* correction) {
    RC_RANGE_ITEM(q);
    params.near_visibility = 0;
    const NearField near = rc_decomp_near_field(near_grid, near_start, near_list, near_triangles,
                                                radiance, &params, 0);
    ShSample none;
    for (int i = 0; i < RC_DECOMP_SH_COEFFICIENTS; ++i) {
        none.coefficients[i] = (float4)(0.0f);
    }
    uint count = 0;
    uint rays = 0;
    const float3 sum = rc_decomp_near_correction(&near, &none, points[q].xyz, points[q].xyz,
                                                 normals[q].xyz, &count, &rays);
    correction[q] = (float4)(sum, (float)count);
}

// Item i: point i % count of split triangle split[i / count] (rc_decomp_triangle_ray) found two
// ways: rc_decomp_triangle_hit's primitive and position into placed_primitives[i], placed[i];
// and the closest hit of the point's ray traced through the scene into traced_primitives[i],
// traced[i] (RC_NO_HIT and 0 for a miss).
RC_KERNEL void decomp_triangle_points(uint begin, uint end, DecompParams params,
                                      RC_SCENE_PARAMETERS, __global const NearTriangle* split,
                                      int count, __global uint* placed_primitives,
                                      __global float4* placed, __global uint* traced_primitives,
                                      __global float4* traced) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    const uint t = i / (uint)count;
    RngStream rng;
    const Ray ray = rc_decomp_triangle_ray(&params, split + t, t, i % (uint)count, count, &rng);
    const Hit hit = rc_decomp_triangle_hit(&scene, split + t, ray);
    placed_primitives[i] = hit.primitive;
    placed[i] = (float4)(0.0f);
    if (hit.primitive != RC_NO_HIT) {
        placed[i] = (float4)(rc_surface_point(&scene, ray, hit).position, 0.0f);
    }
    const Hit found = rc_trace_closest(scene.nodes, scene.triangles, ray);
    traced_primitives[i] = found.primitive;
    traced[i] = (float4)(0.0f);
    if (found.primitive != RC_NO_HIT) {
        traced[i] = (float4)(rc_surface_point(&scene, ray, found).position, 0.0f);
    }
}
