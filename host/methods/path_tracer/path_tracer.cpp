#include "methods/path_tracer/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image/film.h"
#include "image/sample_sums.h"
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

Image PathTracer::resolve(const std::vector<shared::float4>& film, int width,
                          const PixelWindow& window, Image* sums_out) {
    // The sums become means over the pixel's finite samples (the beauty slot's w), and the sums
    // of squares the standard deviation of one sample, unbiased variance estimate (that of the
    // mean is stddev / sqrt(n)): unlike the mean's variance it keeps its precision in half floats.
    std::vector<shared::float4> cut(static_cast<size_t>(window.width()) * window.height() *
                                    RC_PT_FILM_SLOTS);
    for (int y = window.y0; y < window.y1; ++y) {
        const auto from =
            film.begin() + (static_cast<ptrdiff_t>(y) * width + window.x0) * RC_PT_FILM_SLOTS;
        std::copy(from, from + static_cast<ptrdiff_t>(window.width()) * RC_PT_FILM_SLOTS,
                  cut.begin() +
                      static_cast<ptrdiff_t>(y - window.y0) * window.width() * RC_PT_FILM_SLOTS);
    }
    Image sums = film_sums(cut, window.width(), window.height());
    Image image = resolve_sums(sums);
    if (sums_out != nullptr) {
        *sums_out = std::move(sums);
    }
    return image;
}

shared::PathTracerParams PathTracer::pass_params(const PathTracerOptions& options, int width,
                                                 int height) {
    shared::PathTracerParams params{};
    params.width = width;
    params.height = height;
    set_kernel_path_settings(options, &params);
    return params;
}

namespace {

// The window of `options` in a width x height image: the whole image when none is given; Error
// (exit status 2) naming --crop when it reaches outside the image.
PixelWindow render_window(const PathTracerOptions& options, int width, int height) {
    if (options.crop.empty()) {
        return {0, width, 0, height};
    }
    const PixelWindow& c = options.crop;
    if (c.x0 < 0 || c.y0 < 0 || c.x1 > width || c.y1 > height) {
        throw Error("--crop " + std::to_string(c.x0) + ":" + std::to_string(c.x1) + "," +
                        std::to_string(c.y0) + ":" + std::to_string(c.y1) +
                        " reaches outside the image (" + std::to_string(width) + "x" +
                        std::to_string(height) + ")",
                    kExitUsage);
    }
    return c;
}

}  // namespace

PathTracerStats PathTracer::render_passes(const PathTracerOptions& options,
                                          const PixelWindow& window, Buffer<shared::float4>& film) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    Buffer<unsigned> counters(context_, 3, "path_counters");
    shared::PathTracerParams params = pass_params(options, width, height);
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    // A window as wide as the image is one range of pixels; another, a range per row.
    const bool whole_rows = window.x0 == 0 && window.x1 == width;
    PathTracerStats result;
    const auto start = SteadyClock::now();
    auto elapsed = [&] { return seconds_since(start); };
    for (int pass = 0;; ++pass) {
        if (options.time_limit > 0.0 ? (pass > 0 && elapsed() >= options.time_limit)
                                     : pass >= options.spp) {
            break;
        }
        params.sample = options.first_sample + pass;
        const std::vector<unsigned> zero = {0u, 0u, 0xffffffffu};
        counters.upload(zero);
        for (int y = window.y0; y < window.y1; y = whole_rows ? window.y1 : y + 1) {
            const size_t row = static_cast<size_t>(y) * width;
            const size_t last_row = whole_rows ? static_cast<size_t>(window.y1 - 1) * width : row;
            context_.launch_range(kernel_, row + window.x0, last_row + window.x1, params, camera,
                                  SceneArguments(bvh_, device_scene_), film, counters);
        }
        const std::vector<unsigned> c = counters.download();
        result.rays += c[0];
        result.nonfinite_samples += c[1];
        if (c[1] > 0 && result.first_nonfinite_pixel < 0) {
            result.first_nonfinite_pixel = c[2];
        }
        result.spp = pass + 1;
        if (options.on_power_of_two && (result.spp & (result.spp - 1)) == 0) {
            options.on_power_of_two(result.spp, resolve(film.download(), width, window));
        }
        if (options.on_progress) {
            options.on_progress(options.time_limit > 0.0
                                    ? std::min(1.0, elapsed() / options.time_limit)
                                    : static_cast<double>(result.spp) / options.spp,
                                result.spp);
        }
    }
    result.seconds = elapsed();
    return result;
}

Image PathTracer::render(const PathTracerOptions& options, PathTracerStats* stats) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    check_film_size(width, height, context_.device());
    const PixelWindow window = render_window(options, width, height);
    if (options.spp < 1 && options.time_limit <= 0.0) {
        throw Error("samples per pixel must be at least 1", kExitUsage);
    }
    if (frame_.peers != nullptr && !frame_.peers->empty()) {
        const std::string devices = std::to_string(frame_.peers->size() + 1);
        if (!options.crop.empty()) {
            throw Error("--crop renders on one device; --device names " + devices, kExitUsage);
        }
        if (options.first_sample != 0) {
            throw Error("--sample-range renders on one device; --device names " + devices,
                        kExitUsage);
        }
        return render_split(options, width, height, stats);
    }
    const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
    Buffer<shared::float4> film(context_, count * RC_PT_FILM_SLOTS, "film");
    film.fill_zero();
    const PathTracerStats result = render_passes(options, window, film);
    if (stats != nullptr) {
        *stats = result;
    }
    return resolve(film.download(), width, window, options.sums);
}

}  // namespace rc
