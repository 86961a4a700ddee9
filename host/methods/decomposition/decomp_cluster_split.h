// Irradiance decomposition's cluster batches on several devices (§4.1's rays and fits):
// a batch's clusters in ranges shared among the devices (methods/device_split.h). A cluster's
// rays read only its own members' camera samples and its own random stream, and its fit only its
// rays, so neither depends on the device; the host gathers the fits in cluster order. Only with
// path-traced continuation as the coarse solution (--decomp-source path): the irradiance vector
// grid lives on the first device, where its batches stay. The camera samples are uploaded to each
// peer once.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "methods/frame_scene.h"
#include "shared/decomposition.h"
#include "shared/types.h"

namespace rc {

// One device's share of a frame's cluster batches.
struct DecompClusterShare {
    size_t cluster_ranges = 0;
    size_t clusters = 0;
    uint64_t cluster_rays = 0;
    double seconds = 0.0;  // its threads' time over the batches
};

class DecompClusterSplit {
   public:
    // The frame's device and its peers (frame.peers: not empty); the camera samples on the first
    // device and on the host; the program's build options (path-traced continuation's).
    DecompClusterSplit(const FrameScene& frame, const Buffer<shared::GBufferSample>& gbuffer,
                       const std::vector<shared::GBufferSample>& samples,
                       const std::string& build_options);
    ~DecompClusterSplit();

    // The fits of a batch's `clusters` (members[first_member ..] their G-buffer entries), in
    // cluster order; the rays traced added to *rays.
    std::vector<shared::ClusterFit> fit_batch(const shared::DecompParams& params,
                                              const std::vector<shared::DecompCluster>& clusters,
                                              const std::vector<uint32_t>& members, uint64_t* rays);

    const std::vector<DecompClusterShare>& shares() const { return shares_; }

   private:
    struct Device;
    const Buffer<shared::GBufferSample>& gbuffer_;  // on the first device
    std::vector<std::unique_ptr<Device>> devices_;
    std::vector<DecompClusterShare> shares_;
};

}  // namespace rc
