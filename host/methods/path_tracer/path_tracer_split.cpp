// The path tracer on several devices (issue 14; PathTracer::render with the frame's peers): the
// image's rows in chunks taken in turn by one thread per device as it finishes its last, every
// pass of a chunk on the device that took it, the films merged by chunk.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

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
// counters, and what it did.
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
    std::vector<size_t> chunks;  // indices, in the order taken
    uint64_t rays = 0;
    uint64_t nonfinite = 0;
    int64_t first_nonfinite = -1;  // the smallest pixel index with one
    double seconds = 0.0;
};

// What the device threads share: the next chunk, how many are done, and the first failure.
struct SplitQueue {
    size_t chunk_pixels = 0;
    size_t pixels = 0;
    size_t chunk_count = 0;
    std::atomic<size_t> next{0};
    std::atomic<size_t> done{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::string error;
    int exit_code = kExitFailure;
};

std::string device_label(const Context& context) {
    return "device " + context.device().spec() + " (" + context.device().name + ")";
}

// Every pass of chunk `chunk` on `work`'s device.
void render_chunk(DeviceWork& work, SplitQueue& queue, size_t chunk,
                  shared::PathTracerParams params, const shared::CameraParams& camera, int spp) {
    const size_t begin = chunk * queue.chunk_pixels;
    const size_t end = std::min(queue.pixels, begin + queue.chunk_pixels);
    const SceneArguments scene(work.frame.bvh, work.frame.device_scene);
    for (int pass = 0; pass < spp && !queue.failed; ++pass) {
        params.sample = pass;
        work.counters.upload({0u, 0u, 0xffffffffu});
        work.frame.context.launch_range(work.kernel, begin, end, params, camera, scene, work.film,
                                        work.counters);
        const std::vector<unsigned> c = work.counters.download();
        work.rays += c[0];
        work.nonfinite += c[1];
        if (c[1] > 0 &&
            (work.first_nonfinite < 0 || static_cast<int64_t>(c[2]) < work.first_nonfinite)) {
            work.first_nonfinite = c[2];
        }
    }
}

// Device `index`'s thread: chunk `index` first (so that every device renders one when there are
// enough), then the next chunk left until none is or a device failed.
void run_device(size_t index, DeviceWork& work, SplitQueue& queue,
                const shared::PathTracerParams& params, const shared::CameraParams& camera,
                int spp) {
    const auto start = SteadyClock::now();
    try {
        for (size_t chunk = index; chunk < queue.chunk_count && !queue.failed;
             chunk = queue.next++) {
            render_chunk(work, queue, chunk, params, camera, spp);
            work.chunks.push_back(chunk);
            ++queue.done;
        }
    } catch (const std::exception& e) {
        const std::lock_guard<std::mutex> lock(queue.mutex);
        if (!queue.failed.exchange(true)) {
            queue.error = device_label(work.frame.context) + ": " + e.what();
            const auto* error = dynamic_cast<const Error*>(&e);
            queue.exit_code = error != nullptr ? error->exit_code() : kExitFailure;
        }
    }
    work.seconds = seconds_since(start);
}

}  // namespace

Image PathTracer::render_split(const PathTracerOptions& options, int width, int height,
                               PathTracerStats* stats) {
    if (options.time_limit > 0.0) {
        throw Error("--time renders on one device; --device names " +
                        std::to_string(frame_peers_->size() + 1),
                    kExitUsage);
    }
    if (options.on_power_of_two) {
        throw Error("--save-every-pow2 renders on one device; --device names " +
                        std::to_string(frame_peers_->size() + 1),
                    kExitUsage);
    }
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    std::vector<std::unique_ptr<DeviceWork>> works;
    works.push_back(std::make_unique<DeviceWork>(frame_, pixels));
    for (const FrameScene& peer : *frame_peers_) {
        works.push_back(std::make_unique<DeviceWork>(peer, pixels));
    }
    SplitQueue queue;
    const int rows = std::max(1, height / (kChunksPerDevice * static_cast<int>(works.size())));
    queue.chunk_pixels = static_cast<size_t>(rows) * static_cast<size_t>(width);
    queue.pixels = pixels;
    queue.chunk_count = (pixels + queue.chunk_pixels - 1) / queue.chunk_pixels;
    const shared::PathTracerParams params = pass_params(options, width, height);
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    const auto start = SteadyClock::now();
    std::vector<std::thread> threads;
    queue.next = works.size();  // chunks 0 .. devices - 1 are the devices' first
    for (size_t i = 0; i < works.size(); ++i) {
        threads.emplace_back(run_device, i, std::ref(*works[i]), std::ref(queue), std::cref(params),
                             std::cref(camera), options.spp);
    }
    while (queue.done < queue.chunk_count && !queue.failed) {
        if (options.on_progress) {
            options.on_progress(static_cast<double>(queue.done) / queue.chunk_count, options.spp);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    for (std::thread& thread : threads) {
        thread.join();
    }
    if (queue.failed) {
        throw Error(queue.error, queue.exit_code);
    }
    // Each chunk's pixels from the film of the device that rendered it.
    std::vector<shared::float4> sums(pixels * RC_PT_FILM_SLOTS);
    PathTracerStats result;
    result.spp = options.spp;
    for (const auto& work : works) {
        const std::vector<shared::float4> film = work->film.download();
        PathTracerDeviceShare share;
        share.device =
            work->frame.context.device().spec() + " " + work->frame.context.device().name;
        for (size_t chunk : work->chunks) {
            const size_t begin = chunk * queue.chunk_pixels * RC_PT_FILM_SLOTS;
            const size_t end =
                std::min(pixels, (chunk + 1) * queue.chunk_pixels) * RC_PT_FILM_SLOTS;
            std::copy(film.begin() + static_cast<long>(begin),
                      film.begin() + static_cast<long>(end),
                      sums.begin() + static_cast<long>(begin));
            share.pixels += (end - begin) / RC_PT_FILM_SLOTS;
        }
        share.chunks = work->chunks.size();
        share.rays = work->rays;
        share.seconds = work->seconds;
        result.rays += work->rays;
        result.nonfinite_samples += work->nonfinite;
        if (work->first_nonfinite >= 0 && (result.first_nonfinite_pixel < 0 ||
                                           work->first_nonfinite < result.first_nonfinite_pixel)) {
            result.first_nonfinite_pixel = work->first_nonfinite;
        }
        result.devices.push_back(share);
    }
    result.seconds = seconds_since(start);
    if (options.on_progress) {
        options.on_progress(1.0, options.spp);
    }
    if (stats != nullptr) {
        *stats = result;
    }
    return resolve(std::move(sums), width, height);
}

}  // namespace rc
