#include "methods/normals/normals.h"

#include <memory>

#include "image/film.h"
#include "methods/device_split.h"
#include "scene/camera.h"
#include "util/error.h"

namespace rc {

namespace {

// 1 where the render's samples are jittered (NormalsOptions::jitter).
unsigned jitter_flag(const NormalsOptions& options) {
    return options.jitter == NormalsOptions::Jitter::kAlways || options.samples_per_pixel > 1 ||
                   options.first_sample > 0
               ? 1u
               : 0u;
}

}  // namespace

NormalsMethod::NormalsMethod(const FrameScene& frame)
    : FrameBound(frame),
      frame_(frame),
      kernel_(frame.context.kernel("normals/normals.cl", "render_normals")) {}

Image NormalsMethod::render(const NormalsOptions& options,
                            std::vector<NormalsDeviceShare>* devices) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    if (options.samples_per_pixel == 0) {
        throw Error("samples per pixel must be at least 1", kExitUsage);
    }
    if (options.first_sample > 0xffffffffu - options.samples_per_pixel) {
        throw Error("normals: camera sample indices beyond 2^32", kExitUsage);
    }
    if (frame_.peers != nullptr && !frame_.peers->empty()) {
        return unpack_film(render_split(options, width, height, devices), 1, width, height,
                           {{"beauty", 0}});
    }
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    Buffer<shared::float4> film(context_, pixels, "film");
    const auto seed_lo = static_cast<unsigned>(options.seed);
    const auto seed_hi = static_cast<unsigned>(options.seed >> 32);
    context_.launch(kernel_, pixels, camera, bvh_.nodes, bvh_.triangles, bvh_.triangle_of_primitive,
                    options.first_sample, options.samples_per_pixel, jitter_flag(options), seed_lo,
                    seed_hi, film);
    return unpack_film(film.download(), 1, width, height, {{"beauty", 0}});
}

std::vector<shared::float4> NormalsMethod::render_split(const NormalsOptions& options, int width,
                                                        int height,
                                                        std::vector<NormalsDeviceShare>* devices) {
    // One device's part: its frame, kernel and film of the whole image (only its chunks drawn).
    struct DeviceWork {
        const FrameScene& frame;
        Kernel kernel;
        Buffer<shared::float4> film;
    };
    const PixelChunks chunks(width, height, frame_.peers->size() + 1);
    std::vector<std::unique_ptr<DeviceWork>> works;
    std::vector<Context*> contexts;
    for (size_t d = 0; d <= frame_.peers->size(); ++d) {
        const FrameScene& frame = d == 0 ? frame_ : (*frame_.peers)[d - 1];
        works.push_back(std::make_unique<DeviceWork>(
            DeviceWork{frame, frame.context.kernel("normals/normals.cl", "render_normals"),
                       Buffer<shared::float4>(frame.context, chunks.pixels, "film")}));
        contexts.push_back(&frame.context);
    }
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    const auto seed_lo = static_cast<unsigned>(options.seed);
    const auto seed_hi = static_cast<unsigned>(options.seed >> 32);
    const DeviceSplit split = run_device_split(
        contexts, chunks.count,
        [&](size_t d, size_t chunk, const std::atomic<bool>&) {
            DeviceWork& work = *works[d];
            const auto [begin, end] = chunks.range(chunk);
            work.frame.context.launch_range(
                work.kernel, begin, end, camera, work.frame.bvh.nodes, work.frame.bvh.triangles,
                work.frame.bvh.triangle_of_primitive, options.first_sample,
                options.samples_per_pixel, jitter_flag(options), seed_lo, seed_hi, work.film);
        },
        {});
    std::vector<shared::float4> image(chunks.pixels);
    for (size_t d = 0; d < works.size(); ++d) {
        const Context& context = works[d]->frame.context;
        NormalsDeviceShare share;
        share.device = context.device().spec() + " " + context.device().name;
        share.chunks = split.items[d].size();
        share.pixels = copy_chunks(chunks, split.items[d], works[d]->film.download(), 1, image);
        share.seconds = split.seconds[d];
        if (devices != nullptr) {
            devices->push_back(share);
        }
    }
    return image;
}

}  // namespace rc
