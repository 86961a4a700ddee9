// A camera sample as the glossy caches see it (radiance caching, DESIGN.md §6.4; SDRC, §6.5).
#pragma once

#include "caching/pipeline_shading.h"
#include "shared/radiance_cache.h"

// The camera sample s of a pixel: the hit of the same camera ray the irradiance cache's passes
// trace (rc_ic_camera_ray), its shading frame, w_o, pixel footprint and triangle, order -1.
// *glossy: its material has a specular lobe to cache and the depth limit leaves a bounce for
// indirect light.
RC_FUNC RcQuery rc_glossy_camera_query(const SceneData* scene, const IcParams* params,
                                       const CameraParams* camera, uint pixel, uint s,
                                       bool* glossy) {
    RcQuery q;
    q.position = q.origin = q.normal = q.tangent = q.geometric_normal = q.outgoing = (float4)(0.0f);
    q.footprint = 0.0f;
    q.material = -1;
    q.order = -1;
    q.primitive = -1;
    *glossy = false;
    RngStream rng;
    float x, y;
    const Ray ray = rc_ic_camera_ray(params, camera, pixel, s, &rng, &x, &y);
    const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
    if (hit.primitive == RC_NO_HIT) {
        return q;
    }
    const SurfacePoint sp = rc_surface_point(scene, ray, hit);
    const SurfaceMaterial material = rc_surface_material(scene, &sp);
    q.position = (float4)(sp.position, 0.0f);
    q.origin = (float4)(sp.origin, 0.0f);
    q.normal = (float4)(sp.shading.n, 0.0f);
    q.tangent = (float4)(sp.shading.t, 0.0f);
    q.geometric_normal = (float4)(sp.geometric_normal, 0.0f);
    q.outgoing = (float4)(rc_to_local(&sp.shading, -ray.direction.xyz), 0.0f);
    q.footprint = rc_ic_pixel_footprint(camera, x, y, hit.t);
    q.material = sp.material;
    q.primitive = (int)hit.primitive;
    *glossy = rc_material_has_glossy_lobe(&material) && params->max_depth >= 2;
    return q;
}

// A query's shading frame (the frame of its w_o and of its BRDF coefficients).
RC_FUNC Frame rc_query_frame(const RcQuery* q) {
    Frame f;
    f.n = q->normal.xyz;
    f.t = q->tangent.xyz;
    f.b = cross(f.n, f.t);
    return f;
}
