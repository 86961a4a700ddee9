// The geometry preview: shaded normals of the first hit seen through the device BVH.
#pragma once

#include "common/bvh_traversal.h"
#include "common/camera.h"
#include "common/pixel_sampler.h"
#include "common/triangle_geometry.h"
#include "shared/rng.h"
#include "shared/types.h"

// Colour of one camera sample: the normal facing the camera mapped to [0, 1]^3, darkened by the
// cosine to the viewer; black where the ray escapes.
RC_FUNC float3 rc_normals_sample(const CameraParams* camera, RC_GLOBAL const TraversalNode* nodes,
                                 RC_GLOBAL const Triangle* triangles,
                                 RC_GLOBAL const uint* triangle_of_primitive, float x, float y) {
    const Ray ray = rc_camera_ray(camera, x, y);
    const Hit hit = rc_trace_closest(nodes, triangles, ray);
    if (hit.primitive == RC_NO_HIT) {
        return (float3)(0.0f);
    }
    float3 n = rc_triangle_normal(triangles + triangle_of_primitive[hit.primitive]);
    const float cosine = dot(n, ray.direction.xyz);
    if (cosine > 0.0f) {
        n = -n;
    }
    return (0.5f * n + 0.5f) * (0.25f + 0.75f * fabs(cosine));
}

// The pixel's value: the mean of camera samples first .. first + samples - 1, jittered (the
// pixel sampler's positions) when `jitter` is 1, else the one sample at the pixel's centre.
RC_FUNC float4 rc_normals_pixel(const CameraParams* camera, RC_GLOBAL const TraversalNode* nodes,
                                RC_GLOBAL const Triangle* triangles,
                                RC_GLOBAL const uint* triangle_of_primitive, uint pixel, uint first,
                                uint samples, uint jitter, uint seed_lo, uint seed_hi) {
    float3 sum = (float3)(0.0f);
    for (uint s = 0; s < samples; ++s) {
        float2 position = (float2)((float)(pixel % (uint)camera->resolution.x) + 0.5f,
                                   (float)(pixel / (uint)camera->resolution.x) + 0.5f);
        if (jitter != 0u) {
            RngStream rng;
            position = rc_camera_sample_position(camera, seed_lo, seed_hi, pixel, first + s, &rng);
        }
        sum += rc_normals_sample(camera, nodes, triangles, triangle_of_primitive, position.x,
                                 position.y);
    }
    return (float4)(sum / (float)samples, 1.0f);
}
