// Test kernels (tests/common/light_sampling_test.cpp, tests/common/direct_light_test.cpp):
// next-event estimation's light sampling from one point, the density MIS evaluates for a direction,
// the spherical-triangle sampler, and the direct light of a Lambertian point.
#include "common/kernel_range.h"
#include "common/light.h"
#include "common/path_radiance.h"
#include "scene_arguments.h"
#include "shared/rng.h"

// Sample i from point p: light index and pdf into choice[i] (x: light, y: pdf, z: delta, w:
// infinite), the direction and the target point into geometry[2i], geometry[2i + 1], the
// radiance into radiance[i].
RC_KERNEL void light_sample_probe(uint begin, uint end, float4 p, uint seed, RC_SCENE_PARAMETERS,
                                  __global float4* choice, __global float4* geometry,
                                  __global float4* radiance) {
    RC_RANGE_ITEM(i);
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

// Item i: the density light sampling gives direction directions[i] from p (the area light the
// ray from p meets first, seen from its emitting side; 0 otherwise), into pdfs[i].
RC_KERNEL void light_pdf_probe(uint begin, uint end, float4 p, RC_SCENE_PARAMETERS,
                               __global const float4* directions, __global float* pdfs) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    Ray ray;
    ray.origin = (float4)(p.xyz, 0.0f);
    ray.direction = (float4)(directions[i].xyz, INFINITY);
    const Hit hit = rc_trace_closest(nodes, triangles, ray);
    float pdf = 0.0f;
    if (hit.primitive != RC_NO_HIT) {
        const SurfacePoint sp = rc_surface_point(&scene, ray, hit);
        if (sp.light >= 0 && sp.front) {
            pdf = rc_area_light_pdf(&scene, sp.light, hit.primitive, p.xyz, sp.position,
                                    sp.geometric_normal);
        }
    }
    pdfs[i] = pdf;
}

// Item i: a direction from (0, 0, 0) uniform in the spherical triangle of unit vertices a, b, c
// (u1, u2 from stream i of `seed`), into directions[i] (w: the solid angle).
RC_KERNEL void spherical_triangle_probe(uint begin, uint end, float4 a, float4 b, float4 c,
                                        uint seed, __global float4* directions) {
    RC_RANGE_ITEM(i);
    RngStream rng = rc_rng_stream(seed, 0u, i, 0u);
    const float u1 = rc_rng_next_float(&rng);
    const float u2 = rc_rng_next_float(&rng);
    const float solid_angle = rc_spherical_triangle_solid_angle(a.xyz, b.xyz, c.xyz);
    directions[i] = (float4)(rc_sample_spherical_triangle(a.xyz, b.xyz, c.xyz, solid_angle, u1, u2),
                             solid_angle);
}

// Item i: the direct light reflected along the normal n by a white Lambertian point p (not on a
// surface of the scene) with `light_samples` light samples and one BRDF sample (stream i of
// `seed`): the light samples' mean into light_part[i] (w: shadow and BRDF rays traced), the BRDF
// sample's part into brdf_part[i]. Their sum estimates E / pi, E the irradiance at p.
RC_KERNEL void direct_light_probe(uint begin, uint end, float4 p, float4 n, int light_samples,
                                  uint seed, RC_SCENE_PARAMETERS, __global float4* light_part,
                                  __global float4* brdf_part) {
    RC_RANGE_ITEM(i);
    const SceneData scene = RC_SCENE_DATA();
    SurfacePoint sp;
    sp.position = sp.origin = p.xyz;
    sp.geometric_normal = sp.shading.n = n.xyz;
    rc_orthonormal_basis(n.xyz, &sp.shading.t, &sp.shading.b);
    sp.uv = (float2)(0.0f, 0.0f);
    sp.material = 0;
    sp.light = -1;
    sp.front = true;
    SurfaceMaterial white;
    white.kind = RC_MATERIAL_DIFFUSE;
    white.diffuse = (float3)(1.0f);
    white.specular = (float3)(0.0f);
    white.exponent = white.alpha_x = white.alpha_y = 0.0f;
    white.diffuse_probability = 1.0f;
    const float3 wo = (float3)(0.0f, 0.0f, 1.0f);
    RngStream rng = rc_rng_stream(seed, 0u, i, 0u);
    uint rays = 0;
    const float3 light = rc_next_event(&scene, &sp, &white, wo, light_samples, &rng, &rays);
    const float3 brdf =
        rc_bsdf_sampled_emission(&scene, &sp, &white, wo, light_samples, &rng, &rays);
    light_part[i] = (float4)(light, (float)rays);
    brdf_part[i] = (float4)(brdf, 0.0f);
}
