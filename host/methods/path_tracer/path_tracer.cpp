#include "methods/path_tracer/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image/film.h"
#include "methods/scene_arguments.h"
#include "methods/shared_settings.h"
#include "scene/camera.h"
#include "shared/film.h"
#include "util/error.h"
#include "util/timing.h"

namespace rc {

const char* const kPathTracerAovs[6] = {"beauty", "direct", "indirect",
                                        "albedo", "normal", "stddev"};

namespace {

std::string gibibytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    return text;
}

}  // namespace

void check_film_size(int width, int height, const DeviceInfo& device) {
    const double pixels = static_cast<double>(width) * static_cast<double>(height);
    const double film_bytes = pixels * RC_PT_FILM_SLOTS * sizeof(shared::float4);
    if (pixels >= 4294967296.0 || film_bytes > static_cast<double>(device.max_allocation)) {
        throw Error("resolution " + std::to_string(width) + "x" + std::to_string(height) +
                        " needs a film of " + gibibytes(film_bytes) +
                        ", more than the largest allocation (" +
                        gibibytes(static_cast<double>(device.max_allocation)) + ") of " +
                        device.name,
                    kExitUsage);
    }
}

PathTracer::PathTracer(const FrameScene& frame)
    : FrameBound(frame),
      frame_(frame),
      kernel_(frame.context.kernel("path_tracer/path_tracer.cl", "path_trace_pass")) {}

Image PathTracer::resolve(std::vector<shared::float4> means, int width, int height) {
    // The sums become means over the pixel's finite samples (the beauty slot's w), and the sums
    // of squares the standard deviation of one sample, unbiased variance estimate (that of the
    // mean is stddev / sqrt(n)): unlike the mean's variance it keeps its precision in half floats.
    const size_t pixels = static_cast<size_t>(width) * height;
    for (size_t p = 0; p < pixels; ++p) {
        shared::float4* s = &means[RC_PT_FILM_SLOTS * p];
        const float n = s[RC_PT_FILM_BEAUTY].w;
        const float inv = n > 0.0f ? 1.0f / n : 0.0f;
        for (int k = 0; k < RC_PT_FILM_SLOTS; ++k) {
            s[k] = {s[k].x * inv, s[k].y * inv, s[k].z * inv, 0.0f};
        }
        const float* mean = &s[RC_PT_FILM_BEAUTY].x;
        float* square = &s[RC_PT_FILM_BEAUTY_SQUARED].x;
        for (int c = 0; c < 3; ++c) {
            square[c] =
                n > 1.0f ? std::sqrt(std::max(0.0f, square[c] - mean[c] * mean[c]) * n / (n - 1.0f))
                         : 0.0f;
        }
    }
    return unpack_film(means, RC_PT_FILM_SLOTS, width, height,
                       {{"beauty", RC_PT_FILM_BEAUTY},
                        {"direct", RC_PT_FILM_DIRECT},
                        {"indirect", RC_PT_FILM_INDIRECT},
                        {"albedo", RC_PT_FILM_ALBEDO},
                        {"normal", RC_PT_FILM_NORMAL},
                        {"stddev", RC_PT_FILM_BEAUTY_SQUARED}});
}

shared::PathTracerParams PathTracer::pass_params(const PathTracerOptions& options, int width,
                                                 int height) {
    shared::PathTracerParams params{};
    params.width = width;
    params.height = height;
    set_kernel_path_settings(options, &params);
    return params;
}

Image PathTracer::render(const PathTracerOptions& options, PathTracerStats* stats) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    check_film_size(width, height, context_.device());
    const double pixels = static_cast<double>(width) * static_cast<double>(height);
    if (options.spp < 1 && options.time_limit <= 0.0) {
        throw Error("samples per pixel must be at least 1", kExitUsage);
    }
    if (frame_.peers != nullptr && !frame_.peers->empty()) {
        return render_split(options, width, height, stats);
    }
    const auto count = static_cast<size_t>(pixels);
    Buffer<shared::float4> film(context_, count * RC_PT_FILM_SLOTS, "film");
    film.fill_zero();
    Buffer<unsigned> counters(context_, 3, "path_counters");

    shared::PathTracerParams params = pass_params(options, width, height);
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);

    PathTracerStats result;
    const auto start = SteadyClock::now();
    auto elapsed = [&] { return seconds_since(start); };
    for (int pass = 0;; ++pass) {
        if (options.time_limit > 0.0 ? (pass > 0 && elapsed() >= options.time_limit)
                                     : pass >= options.spp) {
            break;
        }
        params.sample = pass;
        const std::vector<unsigned> zero = {0u, 0u, 0xffffffffu};
        counters.upload(zero);
        context_.launch(kernel_, count, params, camera, SceneArguments(bvh_, device_scene_), film,
                        counters);
        const std::vector<unsigned> c = counters.download();
        result.rays += c[0];
        result.nonfinite_samples += c[1];
        if (c[1] > 0 && result.first_nonfinite_pixel < 0) {
            result.first_nonfinite_pixel = c[2];
        }
        result.spp = pass + 1;
        if (options.on_power_of_two && (result.spp & (result.spp - 1)) == 0) {
            options.on_power_of_two(result.spp, resolve(film.download(), width, height));
        }
        if (options.on_progress) {
            options.on_progress(options.time_limit > 0.0
                                    ? std::min(1.0, elapsed() / options.time_limit)
                                    : static_cast<double>(result.spp) / options.spp,
                                result.spp);
        }
    }
    result.seconds = elapsed();
    if (stats != nullptr) {
        *stats = result;
    }
    return resolve(film.download(), width, height);
}

}  // namespace rc
