#include "methods/decomposition/decomp_cluster_split.h"

#include <algorithm>

#include "methods/device_split.h"
#include "methods/radiance_source.h"
#include "methods/scene_arguments.h"

namespace rc {
namespace {

constexpr const char* kProgram = "decomposition/decomposition.cl";
// Cluster ranges per device a batch is split into: enough for the faster devices to take more.
constexpr size_t kRangesPerDevice = 4;

}  // namespace

// One device: its frame and kernels, the camera samples (a peer's copy), the current batch's
// members (uploaded by its first range) and rays traced.
struct DecompClusterSplit::Device {
    Device(const FrameScene& frame, const std::string& build_options,
           const std::vector<shared::GBufferSample>* samples)
        : frame(frame),
          rays_kernel(frame.context.kernel(kProgram, "decomp_cluster_rays", build_options)),
          fit_kernel(frame.context.kernel(kProgram, "decomp_fit", build_options)),
          copy(samples != nullptr
                   ? Buffer<shared::GBufferSample>(frame.context, *samples, "decomp_gbuffer")
                   : Buffer<shared::GBufferSample>()) {}

    // The fits of clusters [begin, end) of the batch into fits[begin ..].
    void fit_range(const shared::DecompParams& params,
                   const std::vector<shared::DecompCluster>& clusters, size_t begin, size_t end,
                   const Buffer<shared::GBufferSample>& gbuffer,
                   std::vector<shared::ClusterFit>& fits) {
        Context& context = frame.context;
        const size_t count = end - begin;
        const size_t ray_count = count * static_cast<size_t>(params.cluster_rays);
        const Buffer<shared::DecompCluster> range(
            context,
            std::vector<shared::DecompCluster>(clusters.begin() + static_cast<long>(begin),
                                               clusters.begin() + static_cast<long>(end)),
            "decomp_clusters");
        Buffer<shared::ClusterRay> ray_buffer(context, ray_count, "decomp_cluster_rays");
        Buffer<shared::ClusterFit> fit_buffer(context, count, "decomp_fits");
        Buffer<unsigned> counters(context, 1, "decomp_cluster_counters");
        counters.fill_zero();
        context.launch(rays_kernel, ray_count, params,
                       SceneArguments(frame.bvh, frame.device_scene), path, range, *members,
                       gbuffer, ray_buffer, counters);
        context.launch(fit_kernel, count, params, ray_buffer, fit_buffer);
        const std::vector<shared::ClusterFit> computed = fit_buffer.download();
        std::copy(computed.begin(), computed.end(), fits.begin() + static_cast<long>(begin));
        rays += counters.download()[0];
    }

    FrameScene frame;
    Kernel rays_kernel;
    Kernel fit_kernel;
    Buffer<shared::GBufferSample> copy;
    PathContinuation path;
    std::unique_ptr<Buffer<uint32_t>> members;  // the current batch's
    uint64_t rays = 0;                          // the current batch's
};

DecompClusterSplit::DecompClusterSplit(const FrameScene& frame,
                                       const Buffer<shared::GBufferSample>& gbuffer,
                                       const std::vector<shared::GBufferSample>& samples,
                                       const std::string& build_options)
    : gbuffer_(gbuffer) {
    devices_.push_back(std::make_unique<Device>(frame, build_options, nullptr));
    for (const FrameScene& peer : *frame.peers) {
        devices_.push_back(std::make_unique<Device>(peer, build_options, &samples));
    }
    shares_.resize(devices_.size());
}

DecompClusterSplit::~DecompClusterSplit() = default;

std::vector<shared::ClusterFit> DecompClusterSplit::fit_batch(
    const shared::DecompParams& params, const std::vector<shared::DecompCluster>& clusters,
    const std::vector<uint32_t>& members, uint64_t* rays) {
    const size_t count = clusters.size();
    const ItemRanges ranges(count, devices_.size(), kRangesPerDevice);
    std::vector<shared::ClusterFit> fits(count);
    std::vector<Context*> contexts;
    for (const auto& device : devices_) {
        device->members.reset();
        device->rays = 0;
        contexts.push_back(&device->frame.context);
    }
    const DeviceSplit split = run_device_split(
        contexts, ranges.count,
        [&](size_t d, size_t item, const std::atomic<bool>&) {
            Device& device = *devices_[d];
            if (!device.members) {
                device.members = std::make_unique<Buffer<uint32_t>>(device.frame.context, members,
                                                                    "decomp_members");
            }
            const auto [begin, end] = ranges.range(item);
            device.fit_range(params, clusters, begin, end, d == 0 ? gbuffer_ : device.copy, fits);
        },
        {});
    for (size_t d = 0; d < devices_.size(); ++d) {
        Device& device = *devices_[d];
        device.members.reset();
        *rays += device.rays;
        DecompClusterShare& share = shares_[d];
        share.cluster_ranges += split.items[d].size();
        for (size_t item : split.items[d]) {
            const auto [begin, end] = ranges.range(item);
            share.clusters += end - begin;
        }
        share.cluster_rays += device.rays;
        share.seconds += split.seconds[d];
    }
    return fits;
}

}  // namespace rc
