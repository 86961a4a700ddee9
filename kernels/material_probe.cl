// Test kernels (tests/common/material_test.cpp): sampling, evaluation and pdf of one material for
// one outgoing direction, in the local shading frame.
#include "common/kernel_range.h"
#include "common/material.h"
#include "shared/rng.h"

// Sample i: (wi, pdf) into samples[i] and (the BSDF value, 1 for a delta lobe) into values[i];
// pdf = -1 when the sampler fails (a direction below the surface).
RC_KERNEL void material_sample_probe(uint begin, uint end, Material material, float4 wo, uint seed,
                                     __global float4* samples, __global float4* values) {
    RC_RANGE_ITEM(i);
    const SurfaceMaterial m = rc_surface_material_of(&material);
    RngStream rng = rc_rng_stream(seed, 0u, i, 0u);
    const float u_lobe = rc_rng_next_float(&rng);
    const float u1 = rc_rng_next_float(&rng);
    const float u2 = rc_rng_next_float(&rng);
    BsdfSample s;
    if (rc_material_sample(&m, wo.xyz, u_lobe, u1, u2, &s)) {
        samples[i] = (float4)(s.wi, s.pdf);
        values[i] = (float4)(s.f, s.delta ? 1.0f : 0.0f);
    } else {
        samples[i] = (float4)(0.0f, 0.0f, 0.0f, -1.0f);
        values[i] = (float4)(0.0f);
    }
}

// For direction i: (f, pdf) of the material.
RC_KERNEL void material_eval_probe(uint begin, uint end, Material material, float4 wo,
                                   __global const float4* directions, __global float4* out) {
    RC_RANGE_ITEM(i);
    const SurfaceMaterial m = rc_surface_material_of(&material);
    const float3 wi = directions[i].xyz;
    out[i] = (float4)(rc_material_eval(&m, wo.xyz, wi), rc_material_pdf(&m, wo.xyz, wi));
}

// For microfacet normal i: (D(m), G1(w), the density of normals visible from w D_w(m)) of the
// Trowbridge-Reitz distribution (alpha_x, alpha_y).
RC_KERNEL void microfacet_probe(uint begin, uint end, float alpha_x, float alpha_y, float4 w,
                                __global const float4* normals, __global float4* out) {
    RC_RANGE_ITEM(i);
    TrowbridgeReitz d;
    d.alpha_x = alpha_x;
    d.alpha_y = alpha_y;
    const float3 m = normals[i].xyz;
    out[i] = (float4)(rc_tr_d(d, m), rc_tr_g1(d, w.xyz), rc_tr_visible_d(d, w.xyz, m), 0.0f);
}

// Sample i: a normal drawn from the normals visible from w.
RC_KERNEL void microfacet_sample_probe(uint begin, uint end, float alpha_x, float alpha_y, float4 w,
                                       uint seed, __global float4* samples) {
    RC_RANGE_ITEM(i);
    TrowbridgeReitz d;
    d.alpha_x = alpha_x;
    d.alpha_y = alpha_y;
    RngStream rng = rc_rng_stream(seed, 0u, i, 0u);
    const float u1 = rc_rng_next_float(&rng);
    const float u2 = rc_rng_next_float(&rng);
    samples[i] = (float4)(rc_tr_sample_visible(d, w.xyz, u1, u2), 0.0f);
}
