// One camera sample of the reference path tracer (DESIGN.md §6.1): a jittered camera ray and the
// path-tracing estimator of common/path_radiance.h.
#pragma once

#include "common/camera.h"
#include "common/path_radiance.h"
#include "common/pixel_sampler.h"
#include "shared/rng.h"
#include "shared/types.h"

RC_FUNC PathSample rc_path_sample(const SceneData* scene, const CameraParams* camera,
                                  const PathTracerParams* params, uint pixel) {
    RngStream rng;
    const float2 position = rc_camera_sample_position(camera, params->seed_lo, params->seed_hi,
                                                      pixel, (uint)params->sample, &rng);
    const Ray ray = rc_camera_ray(camera, position.x, position.y);
    return rc_path_radiance(scene, ray, &rng, 0, params->max_depth, params->rr_depth, true);
}
