// Entry kernel of the path tracer (host/methods/path_tracer/): one sample for every pixel,
// accumulated into the film. Each pixel is written by one work item per pass, so the sums are
// deterministic.
#include "common/kernel_range.h"
#include "path_tracer/path_tracer.h"
#include "scene_arguments.h"
#include "shared/film.h"

// film: for each pixel RC_PT_FILM_SLOTS float4 sums (kernels/shared/film.h).
// counters: [0] rays traced, [1] non-finite samples (dropped), [2] first pixel with one.
RC_KERNEL void path_trace_pass(uint begin, uint end, PathTracerParams params, CameraParams camera,
                               RC_SCENE_PARAMETERS, __global float4* film,
                               __global uint* counters) {
    RC_RANGE_ITEM(pixel);
    const SceneData scene = RC_SCENE_DATA();
    const PathSample s = rc_path_sample(&scene, &camera, &params, pixel);
    atomic_add(&counters[0], s.rays);
    if (!all(isfinite(s.radiance)) || !all(isfinite(s.albedo)) || !all(isfinite(s.normal))) {
        atomic_inc(&counters[1]);
        atomic_min(&counters[2], pixel);
        return;
    }
    __global float4* sums = film + RC_PT_FILM_SLOTS * (size_t)pixel;
    sums[RC_PT_FILM_BEAUTY] += (float4)(s.radiance, 1.0f);
    sums[RC_PT_FILM_BEAUTY_SQUARED] += (float4)(s.radiance * s.radiance, 0.0f);
    sums[RC_PT_FILM_DIRECT] += (float4)(s.direct, 0.0f);
    sums[RC_PT_FILM_INDIRECT] += (float4)(s.indirect, 0.0f);
    sums[RC_PT_FILM_ALBEDO] += (float4)(s.albedo, 0.0f);
    sums[RC_PT_FILM_NORMAL] += (float4)(s.normal, 0.0f);
}
