// The path tracer on several devices (PathTracer::render with the frame's peers): the
// image's rows in chunks shared among the devices (methods/device_split.h), every pass of a chunk
// on the device that took it, the films merged by chunk.
#include <algorithm>
#include <memory>

#include "methods/device_shares.h"
#include "methods/device_split.h"
#include "methods/path_tracer/path_tracer.h"
#include "methods/scene_arguments.h"
#include "scene/camera.h"
#include "shared/film.h"
#include "util/error.h"
#include "util/timing.h"

namespace rc {
namespace {

// Chunks per device the rows are split into: enough for the faster devices to take more.
constexpr int kChunksPerDevice = 16;

// One device's part: its frame, kernel, film (the whole image's, only its chunks written) and
// counters, and what it traced.
struct DeviceWork {
    explicit DeviceWork(const FrameScene& frame, size_t pixels)
        : frame(frame),
          kernel(frame.context.kernel("path_tracer/path_tracer.cl", "path_trace_pass")),
          film(frame.context, pixels * RC_PT_FILM_SLOTS, "film"),
          counters(frame.context, 3, "path_counters") {
        film.fill_zero();
    }

    FrameScene frame;
    Kernel kernel;
    Buffer<shared::float4> film;
    Buffer<unsigned> counters;
    uint64_t rays = 0;
    uint64_t nonfinite = 0;
    int64_t first_nonfinite = -1;  // the smallest pixel index with one
};

// Every pass of pixels [begin, end) on `work`'s device, until `stop`.
void render_chunk(DeviceWork& work, size_t begin, size_t end, shared::PathTracerParams params,
                  const shared::CameraParams& camera, int spp, const std::atomic<bool>& stop) {
    const SceneArguments scene(work.frame.bvh, work.frame.device_scene);
    for (int pass = 0; pass < spp && !stop; ++pass) {
        params.sample = pass;
        work.counters.upload({0u, 0u, 0xffffffffu});
        work.frame.context.launch_range(work.kernel, begin, end, params, camera, scene, work.film,
                                        work.counters);
        const std::vector<unsigned> c = work.counters.download();
        work.rays += c[0];
        work.nonfinite += c[1];
        work.first_nonfinite =
            first_nonfinite_of(work.first_nonfinite, c[1] > 0 ? int64_t{c[2]} : -1);
    }
}

}  // namespace

Image PathTracer::render_split(const PathTracerOptions& options, int width, int height,
                               PathTracerStats* stats) {
    const std::string devices = std::to_string(frame_.peers->size() + 1);
    if (options.time_limit > 0.0) {
        throw Error("--time renders on one device; --device names " + devices, kExitUsage);
    }
    if (options.on_power_of_two) {
        throw Error("--save-every-pow2 renders on one device; --device names " + devices,
                    kExitUsage);
    }
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    std::vector<std::unique_ptr<DeviceWork>> works;
    std::vector<Context*> contexts;
    works.push_back(std::make_unique<DeviceWork>(frame_, pixels));
    for (const FrameScene& peer : *frame_.peers) {
        works.push_back(std::make_unique<DeviceWork>(peer, pixels));
    }
    for (const auto& work : works) {
        contexts.push_back(&work->frame.context);
    }
    const PixelChunks chunks(width, height, works.size(), kChunksPerDevice);
    const shared::PathTracerParams params = pass_params(options, width, height);
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    const auto start = SteadyClock::now();
    const DeviceSplit split = run_device_split(
        contexts, chunks.count,
        [&](size_t device, size_t chunk, const std::atomic<bool>& stop) {
            const auto [begin, end] = chunks.range(chunk);
            render_chunk(*works[device], begin, end, params, camera, options.spp, stop);
        },
        [&](double fraction) {
            if (options.on_progress) {
                options.on_progress(fraction, options.spp);
            }
        });
    // Each chunk's pixels from the film of the device that rendered it.
    std::vector<shared::float4> sums(pixels * RC_PT_FILM_SLOTS);
    PathTracerStats result;
    result.spp = options.spp;
    for (size_t d = 0; d < works.size(); ++d) {
        const DeviceWork& work = *works[d];
        const std::vector<shared::float4> film = work.film.download();
        PathTracerDeviceShare share;
        share.device = work.frame.context.device().spec() + " " + work.frame.context.device().name;
        share.pixels = copy_chunks(chunks, split.items[d], film, RC_PT_FILM_SLOTS, sums);
        share.chunks = split.items[d].size();
        share.rays = work.rays;
        share.seconds = split.seconds[d];
        result.rays += work.rays;
        result.nonfinite_samples += work.nonfinite;
        result.first_nonfinite_pixel =
            first_nonfinite_of(result.first_nonfinite_pixel, work.first_nonfinite);
        result.devices.push_back(share);
    }
    result.seconds = seconds_since(start);
    if (options.on_progress) {
        options.on_progress(1.0, options.spp);
    }
    if (stats != nullptr) {
        *stats = result;
    }
    return resolve(sums, width, {0, width, 0, height}, options.sums);
}

}  // namespace rc
