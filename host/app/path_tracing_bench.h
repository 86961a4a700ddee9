// The path tracer's timed render shared by `radcache bench pt` and `radcache bench all`.
#pragma once

#include "methods/frame_scene.h"
#include "methods/path_tracer/path_tracer.h"

namespace rc {

struct PathTracingTime {
    double seconds = 0.0;   // device seconds of path_trace_pass in the timed render
    PathTracerStats stats;  // of the timed render
};

// Path-traces `frame` at width x height with the scene's path depths: one sample per pixel first
// (the warm-up: kernel build and work-group code generation), then the timed `spp` samples per
// pixel.
PathTracingTime time_path_tracing(const FrameScene& frame, int width, int height, int spp);

}  // namespace rc
