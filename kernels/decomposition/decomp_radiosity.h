// The radiosity B(t) of the split triangles (the paper, §6 pass 1: "we also compute the average
// radiosity value over all visible triangles"; §5: eq. 4 reads it as constant over a triangle):
// the points of a triangle it is measured at, and B(t) gathered from the decomposition's own two
// terms there (eq. 3 at the triangle instead of at a camera sample), with no ray beyond the
// point's own and its direct light's.
#pragma once

#include "common/cached_radiance.h"
#include "common/path_radiance.h"
#include "decomposition/decomp_far.h"
#include "decomposition/decomp_shading.h"

// How far above a split triangle its points' rays start: a thousandth of the triangle's size, and
// enough for the coordinates' float precision.
RC_FUNC float rc_decomp_triangle_lift(RC_GLOBAL const NearTriangle* triangle) {
    const float3 v0 = triangle->v0.xyz;
    return 1e-3f * fmax(length(triangle->v1.xyz - v0), length(triangle->v2.xyz - v0)) +
           1e-5f * fmax(fabs(v0.x), fmax(fabs(v0.y), fabs(v0.z)));
}

// Point k of `count` of a split triangle (t its index), stratified over it (Hammersley in the
// unit square, folded), as a ray that arrives at it along its front's normal from
// rc_decomp_triangle_lift above; *rng starts the point's random stream (the same for every pass
// over the triangles).
RC_FUNC Ray rc_decomp_triangle_ray(const DecompParams* params,
                                   RC_GLOBAL const NearTriangle* triangle, uint t, uint k,
                                   int count, RngStream* rng) {
    const float3 v0 = triangle->v0.xyz;
    const float3 e1 = triangle->v1.xyz - v0;
    const float3 e2 = triangle->v2.xyz - v0;
    const float3 normal = normalize(cross(e1, e2));
    const float lift = rc_decomp_triangle_lift(triangle);
    *rng = rc_rng_stream(params->seed_lo ^ RC_DECOMP_RNG_DOMAIN, ~params->seed_hi, t, k);
    float a = ((float)k + rc_rng_next_float(rng)) / (float)count;
    float b = rc_decomp_radical_inverse(k);
    if (a + b > 1.0f) {
        a = 1.0f - a;
        b = 1.0f - b;
    }
    Ray ray;
    ray.origin = (float4)(v0 + a * e1 + b * e2 + lift * normal, 0.0f);
    ray.direction = (float4)(-normal, 2.0f * lift);
    return ray;
}

// Where a split triangle's point ray (rc_decomp_triangle_ray) meets the scene triangle the split
// triangle lies on, without tracing it: that triangle's primitive, the point's barycentric
// coordinates in it and the ray's length to it. No hit for a degenerate triangle.
RC_FUNC Hit rc_decomp_triangle_hit(const SceneData* scene, RC_GLOBAL const NearTriangle* triangle,
                                   Ray ray) {
    Hit hit;
    hit.primitive = RC_NO_HIT;
    hit.t = rc_decomp_triangle_lift(triangle);
    hit.u = hit.v = 0.0f;
    RC_GLOBAL const Triangle* scene_triangle =
        scene->triangles + scene->triangle_of_primitive[triangle->primitive];
    const float3 e1 = scene_triangle->v1.xyz - scene_triangle->v0.xyz;
    const float3 e2 = scene_triangle->v2.xyz - scene_triangle->v0.xyz;
    const float3 d = ray.origin.xyz + hit.t * ray.direction.xyz - scene_triangle->v0.xyz;
    const float d11 = dot(e1, e1);
    const float d12 = dot(e1, e2);
    const float d22 = dot(e2, e2);
    const float determinant = d11 * d22 - d12 * d12;
    if (!(determinant > 0.0f) || !all(isfinite(ray.direction.xyz))) {
        return hit;
    }
    const float u = (d22 * dot(d, e1) - d12 * dot(d, e2)) / determinant;
    const float v = (d11 * dot(d, e2) - d12 * dot(d, e1)) / determinant;
    hit.u = clamp(u, 0.0f, 1.0f);
    hit.v = clamp(v, 0.0f, 1.0f - hit.u);
    hit.primitive = triangle->primitive;
    return hit;
}

// What a split triangle's front sends back along its normal besides its diffuse lobe's indirect
// light (emission left out, as the coarse solution's: decomp_source_rays.h), the mean over
// params->radiosity_samples points of it: the direct light by next-event estimation (one light
// sample) and the other lobes' light by a path sampled from them; and the mean diffuse
// reflectance rho_d at those points in *reflectance. The points lie on the triangle: no ray finds
// them (rc_decomp_triangle_hit). *rays counts the rays traced.
RC_FUNC float3 rc_decomp_triangle_direct(const DecompParams* params, const SceneData* scene,
                                         RC_GLOBAL const NearTriangle* triangle, uint t,
                                         float3* reflectance, uint* rays) {
    const int count = max(params->radiosity_samples, 1);
    float3 sum = (float3)(0.0f);
    *reflectance = (float3)(0.0f);
    for (int k = 0; k < count; ++k) {
        RngStream rng;
        const Ray ray = rc_decomp_triangle_ray(params, triangle, t, (uint)k, count, &rng);
        const Hit hit = rc_decomp_triangle_hit(scene, triangle, ray);
        CachedRadiance c;
        rc_cached_radiance_clear(&c, 0);
        SurfacePoint sp;
        SurfaceMaterial material;
        float3 wo;
        // The ray's path made one bounce before (a camera hit's, as the coarse source's rays).
        if (hit.primitive != RC_NO_HIT &&
            rc_cached_vertex_at(scene, ray, hit, &rng, params->count_emission != 0, true, 1, 1,
                                params->max_depth, &c, &sp, &material, &wo) &&
            2 < params->max_depth) {
            *reflectance += material.diffuse;
            const SurfaceMaterial traced = rc_without_diffuse(&material);
            rc_trace_lobes(scene, &sp, &traced, wo, &rng, 1, params->max_depth, params->rr_depth,
                           &c);
        }
        *rays += c.rays;
        const float3 radiance = c.direct + c.indirect;
        if (all(isfinite(radiance))) {
            sum += radiance;
        }
    }
    *reflectance /= (float)count;
    return sum / (float)count;
}

// B(t) / pi of a split triangle's front path traced (emission left out): the mean over `count`
// stratified points of it of the path tracer's estimate along a ray arriving along its normal;
// for the triangles no far-field sample covers. *rays counts the rays traced.
RC_FUNC float3 rc_decomp_triangle_traced(const DecompParams* params, const SceneData* scene,
                                         RC_GLOBAL const NearTriangle* triangle, uint t, int count,
                                         uint* rays) {
    float3 sum = (float3)(0.0f);
    for (int k = 0; k < count; ++k) {
        RngStream rng;
        const Ray ray = rc_decomp_triangle_ray(params, triangle, t, (uint)k, count, &rng);
        const PathSample s = rc_path_radiance(scene, ray, &rng, 1, params->max_depth,
                                              params->rr_depth, params->count_emission != 0);
        *rays += s.rays;
        if (all(isfinite(s.radiance))) {
            sum += s.radiance;
        }
    }
    return sum / (float)max(count, 1);
}

// Whether the far field covers a split triangle: 0 when some far-field sample's reach holds its
// centroid but none weighs it positively about its front's normal (rc_decomp_sample_weight: a
// face the camera does not see, in an orientation no cluster's rays came from, such as the
// bricks' undersides), where the gather would read a fit made for other orientations and B(t) is
// path traced instead (rc_decomp_triangle_traced); 1 otherwise (covered, or beyond every
// sample's reach: then no camera sample lies within alpha of it, but beside clusters less than
// 4 alpha across, and its B(t) does not reach the image; the gather's fallback serves). With
// `reach_needed` (--decomp-source radiosity, where every B(t) reaches the image through the far
// field's rays) a triangle beyond every sample's reach is not covered either.
RC_FUNC uint rc_decomp_triangle_covered(const FarField* far, RC_GLOBAL const NearTriangle* triangle,
                                        bool reach_needed) {
    const float3 v0 = triangle->v0.xyz;
    const float3 v1 = triangle->v1.xyz;
    const float3 v2 = triangle->v2.xyz;
    const float3 normal = normalize(cross(v1 - v0, v2 - v0));
    const float3 centroid = (v0 + v1 + v2) * (1.0f / 3.0f);
    const int cell = rc_ic_grid_cell(&far->grid, centroid);
    if (!all(isfinite(normal))) {
        return 1;
    }
    if (cell < 0) {
        return reach_needed ? 0u : 1u;
    }
    uint reached = 0;
    for (int k = far->cell_start[cell]; k < far->cell_start[cell + 1]; ++k) {
        RC_GLOBAL const Record* sample = far->samples + far->cell_samples[k];
        if (rc_decomp_sample_weight(sample, centroid, normal) > 0.0f) {
            return 1;
        }
        reached |= length(centroid - sample->position.xyz) < sample->radius ? 1u : 0u;
    }
    return reached != 0 || reach_needed ? 0u : 1u;
}

// B(t) / pi of a split triangle's front gathered from the decomposition (eq. 3 at its centroid
// P_t, normal N_t its front's): `direct` (rc_decomp_triangle_direct) plus
// rho_d / pi max(0, I_D + I_N), I_D from the far-field samples interpolated at P_t and I_N by
// eq. 4 over the near triangles with the radiosities of `near` (the previous pass's), or 0 when
// !with_near (the first pass: the near triangles taken to send what they hide, B(t) = pi L_D*).
// Each further pass is a Jacobi step of the near triangles' exchange; the far field carries the
// light from beyond alpha. *rays counts the shadow rays of --decomp-visibility rays.
RC_FUNC float3 rc_decomp_gathered_radiance(const FarField* far, const NearField* near,
                                           RC_GLOBAL const NearTriangle* triangle, float3 direct,
                                           float3 reflectance, bool with_near, uint* rays) {
    const float3 v0 = triangle->v0.xyz;
    const float3 v1 = triangle->v1.xyz;
    const float3 v2 = triangle->v2.xyz;
    const float3 normal = normalize(cross(v1 - v0, v2 - v0));
    const float3 centroid = (v0 + v1 + v2) * (1.0f / 3.0f);
    if (rc_is_black(reflectance) || !all(isfinite(normal))) {
        return direct;
    }
    GBufferSample g;
    g.position = (float4)(centroid, 0.0f);
    g.normal = (float4)(normal, 0.0f);
    // Where its shadow rays start: off the surface by as much as the triangle radiosity's rays.
    g.origin = (float4)(centroid + 1e-3f * length(v1 - v0) * normal, 0.0f);
    g.footprint = 0.0f;
    g.diffuse = rc_luminance(reflectance);
    g.primitive = -1;
    g.served = 1;
    NearField nearby = *near;
    if (!with_near) {
        nearby.alpha = 0.0f;  // no triangle lies nearer than 0: I_N = 0
    }
    const DecompIrradiance e = rc_decomp_irradiance(far, &nearby, &g);
    *rays += e.near_rays;
    return direct + reflectance * RC_INV_PI * fmax(e.far.xyz + e.near.xyz, (float3)(0.0f));
}
