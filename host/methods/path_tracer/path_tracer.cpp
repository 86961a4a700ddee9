#include "methods/path_tracer/path_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "methods/scene_arguments.h"
#include "scene/camera.h"
#include "util/error.h"

namespace rc {

const char* const kPathTracerAovs[6] = {"beauty", "direct", "indirect",
                                        "albedo", "normal", "stddev"};

namespace {

constexpr size_t kFilmSlots = 6;  // float4 sums per pixel (see kernels/path_tracer/path_tracer.cl)

std::string gibibytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    return text;
}

}  // namespace

PathTracer::PathTracer(Context& context, const Scene& scene, const DeviceBvh& bvh,
                       const DeviceScene& device_scene)
    : context_(context),
      scene_(scene),
      bvh_(bvh),
      device_scene_(device_scene),
      kernel_(context.kernel("path_tracer/path_tracer.cl", "path_trace_pass")) {}

Image PathTracer::resolve(const Buffer<shared::float4>& film, int width, int height) const {
    const std::vector<shared::float4> sums = film.download();
    Image image(width, height, 18);
    image.channel_names.clear();
    for (const char* aov : kPathTracerAovs) {
        for (const char* c : {"R", "G", "B"}) {
            image.channel_names.push_back(
                std::string(aov) == "beauty" ? std::string(c) : std::string(aov) + "." + c);
        }
    }
    const size_t pixels = static_cast<size_t>(width) * height;
    for (size_t p = 0; p < pixels; ++p) {
        const shared::float4* s = &sums[kFilmSlots * p];
        const float n = s[0].w;  // finite samples of this pixel
        const float inv = n > 0.0f ? 1.0f / n : 0.0f;
        float* out = &image.pixels[p * 18];
        const float mean[3] = {s[0].x * inv, s[0].y * inv, s[0].z * inv};
        const float square[3] = {s[1].x * inv, s[1].y * inv, s[1].z * inv};
        for (int c = 0; c < 3; ++c) {
            out[c] = mean[c];
            out[3 + c] = (&s[2].x)[c] * inv;
            out[6 + c] = (&s[3].x)[c] * inv;
            out[9 + c] = (&s[4].x)[c] * inv;
            out[12 + c] = (&s[5].x)[c] * inv;
            // Standard deviation of one sample, unbiased variance estimate (that of the mean is
            // stddev / sqrt(n)): unlike the mean's variance it keeps its precision in half floats.
            out[15 + c] =
                n > 1.0f ? std::sqrt(std::max(0.0f, square[c] - mean[c] * mean[c]) * n / (n - 1.0f))
                         : 0.0f;
        }
    }
    return image;
}

Image PathTracer::render(const PathTracerOptions& options, PathTracerStats* stats) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    const double pixels = static_cast<double>(width) * static_cast<double>(height);
    const double film_bytes = pixels * kFilmSlots * sizeof(shared::float4);
    if (pixels >= 4294967296.0 ||
        film_bytes > static_cast<double>(context_.device().max_allocation)) {
        throw Error("resolution " + std::to_string(width) + "x" + std::to_string(height) +
                        " needs a film of " + gibibytes(film_bytes) +
                        ", more than the largest allocation (" +
                        gibibytes(static_cast<double>(context_.device().max_allocation)) + ") of " +
                        context_.device().name,
                    kExitUsage);
    }
    if (options.spp < 1 && options.time_limit <= 0.0) {
        throw Error("samples per pixel must be at least 1", kExitUsage);
    }
    const auto count = static_cast<size_t>(pixels);
    Buffer<shared::float4> film(context_, count * kFilmSlots, "film");
    film.fill_zero();
    Buffer<unsigned> counters(context_, 3, "path_counters");

    shared::PathTracerParams params{};
    params.width = width;
    params.height = height;
    params.max_depth = options.max_depth;
    params.rr_depth = options.rr_depth;
    params.seed_lo = static_cast<unsigned>(options.seed);
    params.seed_hi = static_cast<unsigned>(options.seed >> 32);
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);

    PathTracerStats result;
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
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
            options.on_power_of_two(result.spp, resolve(film, width, height));
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
    return resolve(film, width, height);
}

}  // namespace rc
