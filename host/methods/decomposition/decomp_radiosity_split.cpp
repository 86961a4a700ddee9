#include "methods/decomposition/decomp_radiosity_split.h"

#include <algorithm>
#include <memory>

#include "methods/device_split.h"
#include "methods/radiance_source.h"
#include "methods/scene_arguments.h"

namespace rc {
namespace {

constexpr const char* kProgram = "decomposition/decomposition.cl";
constexpr size_t kRangesPerDevice = 4;  // enough for the faster devices to take more

// One device: its kernel, the triangles (a peer's copy), the list, its own radiance buffer of
// every triangle (only its ranges written) and its rays.
struct RadiosityDevice {
    RadiosityDevice(const FrameScene& frame, const std::string& build_options,
                    const std::vector<shared::NearTriangle>* copy,
                    const Buffer<shared::NearTriangle>& first, const std::vector<uint32_t>& listed)
        : frame(frame),
          kernel(frame.context.kernel(kProgram, "decomp_radiosity", build_options)),
          own(copy != nullptr
                  ? Buffer<shared::NearTriangle>(frame.context, *copy, "decomp_triangles")
                  : Buffer<shared::NearTriangle>()),
          triangles(copy != nullptr ? own : first),
          list(frame.context, listed, "decomp_radiosity_list"),
          radiance(frame.context, first.size(), "decomp_radiance"),
          counters(frame.context, std::vector<unsigned>{0u}, "decomp_radiosity_counters") {}

    FrameScene frame;
    Kernel kernel;
    Buffer<shared::NearTriangle> own;
    const Buffer<shared::NearTriangle>& triangles;
    Buffer<uint32_t> list;
    Buffer<shared::float4> radiance;
    Buffer<unsigned> counters;
    PathContinuation path;
};

}  // namespace

uint64_t split_coarse_radiosity(const FrameScene& frame, const shared::DecompParams& params,
                                const std::string& build_options,
                                const std::vector<shared::NearTriangle>& triangles,
                                const Buffer<shared::NearTriangle>& first_triangles,
                                const std::vector<uint32_t>& listed,
                                Buffer<shared::float4>& radiance,
                                std::vector<DecompRadiosityShare>* shares) {
    std::vector<std::unique_ptr<RadiosityDevice>> devices;
    devices.push_back(
        std::make_unique<RadiosityDevice>(frame, build_options, nullptr, first_triangles, listed));
    for (const FrameScene& peer : *frame.peers) {
        devices.push_back(std::make_unique<RadiosityDevice>(peer, build_options, &triangles,
                                                            first_triangles, listed));
    }
    std::vector<Context*> contexts;
    for (const auto& device : devices) {
        contexts.push_back(&device->frame.context);
    }
    const size_t count = listed.size();
    const ItemRanges ranges(count, devices.size(), kRangesPerDevice);
    const DeviceSplit split = run_device_split(
        contexts, ranges.count,
        [&](size_t d, size_t item, const std::atomic<bool>&) {
            RadiosityDevice& device = *devices[d];
            const auto [begin, end] = ranges.range(item);
            device.frame.context.launch_range(
                device.kernel, begin, end, params,
                SceneArguments(device.frame.bvh, device.frame.device_scene), device.path,
                device.triangles, device.list, device.radiance, device.counters);
        },
        {});
    // B(t) gathered by range: entry listed[i] from the device that computed the range holding i.
    std::vector<shared::float4> merged = radiance.download();
    uint64_t rays = 0;
    shares->assign(devices.size(), {});
    for (size_t d = 0; d < devices.size(); ++d) {
        const std::vector<shared::float4> computed = devices[d]->radiance.download();
        for (size_t item : split.items[d]) {
            const auto [begin, end] = ranges.range(item);
            for (size_t i = begin; i < end; ++i) {
                merged[listed[i]] = computed[listed[i]];
            }
            (*shares)[d].triangles += end - begin;
        }
        const uint64_t device_rays = devices[d]->counters.download()[0];
        (*shares)[d].rays = device_rays;
        (*shares)[d].seconds = split.seconds[d];
        rays += device_rays;
    }
    radiance.upload(merged);
    return rays;
}

}  // namespace rc
