#include "app/path_tracing_bench.h"

namespace rc {

PathTracingTime time_path_tracing(const FrameScene& frame, int width, int height, int spp) {
    PathTracer tracer(frame);
    PathTracerOptions options;
    options.width = width;
    options.height = height;
    options.spp = 1;
    options.max_depth = frame.scene.render.max_depth;
    options.rr_depth = frame.scene.render.rr_depth;
    tracer.render(options);
    const double before = frame.context.kernel_times().at("path_trace_pass").seconds;
    options.spp = spp;
    PathTracingTime time;
    tracer.render(options, &time.stats);
    time.seconds = frame.context.kernel_times().at("path_trace_pass").seconds - before;
    return time;
}

}  // namespace rc
