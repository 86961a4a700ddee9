// Pinhole camera rays.
#pragma once

#include "shared/types.h"

// The primary ray through image position (x, y) in pixels, (0, 0) the top-left corner.
RC_FUNC Ray rc_camera_ray(const CameraParams* camera, float x, float y) {
    const float3 direction = camera->top_left.xyz +
                             camera->right.xyz * (x / (float)camera->resolution.x) +
                             camera->down.xyz * (y / (float)camera->resolution.y);
    Ray ray;
    ray.origin = (float4)(camera->origin.xyz, 0.0f);
    ray.direction = (float4)(normalize(direction), INFINITY);
    return ray;
}
