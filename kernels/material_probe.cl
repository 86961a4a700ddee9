// Test kernels (tests/common/material_test.cpp): sampling, evaluation and pdf of one material for
// one outgoing direction, in the local shading frame.
#include "common/kernel_range.h"
#include "common/material.h"
#include "shared/rng.h"

// Sample i: (wi, pdf) into samples[i] and the BRDF value into values[i]; pdf = -1 when the
// sampler fails (a direction below the surface).
RC_KERNEL void material_sample_probe(uint begin, uint end, Material material, float4 wo, uint seed,
                                     __global float4* samples, __global float4* values) {
    RC_RANGE_ITEM(i);
    const SurfaceMaterial m = rc_surface_material_of(&material);
    RngStream rng = rc_rng_stream(seed, 0u, i, 0u);
    const float u_lobe = rc_rng_next_float(&rng);
    const float u1 = rc_rng_next_float(&rng);
    const float u2 = rc_rng_next_float(&rng);
    float3 wi;
    float pdf;
    float3 f;
    if (rc_material_sample(&m, wo.xyz, u_lobe, u1, u2, &wi, &pdf, &f)) {
        samples[i] = (float4)(wi, pdf);
        values[i] = (float4)(f, 0.0f);
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
