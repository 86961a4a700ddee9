// Test kernels (tests/light_sampling_test.cpp): next-event estimation's light sampling from one
// point.
#include "common/light.h"
#include "scene_arguments.h"
#include "shared/rng.h"

// Sample i from point p: light index and pdf into choice[i] (x: light, y: pdf, z: delta, w:
// infinite), the direction and the target point into geometry[2i], geometry[2i + 1], the
// radiance into radiance[i].
__kernel void light_sample_probe(uint begin, uint end, float4 p, uint seed, RC_SCENE_PARAMETERS,
                                 __global float4* choice, __global float4* geometry,
                                 __global float4* radiance) {
    const uint i = begin + (uint)get_global_id(0);
    if (i >= end) {
        return;
    }
    const SceneData scene = RC_SCENE_DATA();
    RngStream rng = rc_rng_stream(seed, 0u, i, 0u);
    const float u = rc_rng_next_float(&rng);
    const float u1 = rc_rng_next_float(&rng);
    const float u2 = rc_rng_next_float(&rng);
    const float u3 = rc_rng_next_float(&rng);
    const int l = rc_sample_cdf(light_cdf, light_count, u);
    const LightSample s =
        rc_sample_light(&scene, l, rc_cdf_probability(light_cdf, l), p.xyz, u1, u2, u3);
    choice[i] = (float4)((float)l, s.pdf, s.delta ? 1.0f : 0.0f, s.infinite ? 1.0f : 0.0f);
    geometry[2 * i] = (float4)(s.direction, 0.0f);
    geometry[2 * i + 1] = (float4)(s.target, 0.0f);
    radiance[i] = (float4)(s.radiance, 0.0f);
}
