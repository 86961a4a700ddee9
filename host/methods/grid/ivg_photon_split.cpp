// The grid's photons on several devices (IrradianceVectorGrid::trace_photons with the
// frame's peers): photon batches shared among the devices (methods/device_split.h), each device
// depositing into its own fixed-point sums; the sums are added on the host and uploaded to the
// frame's device. Integer addition is exact in any order, so the grid, and every image read from
// it, is bitwise the one-device grid whatever the split.
#include <algorithm>
#include <memory>

#include "methods/device_split.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/scene_arguments.h"
#include "util/timing.h"

namespace rc {
namespace {

// Batches per device the photons are split into (at most kLargestBatch photons each).
constexpr uint64_t kBatchesPerDevice = 8;
constexpr uint64_t kLargestBatch = uint64_t{1} << 22;
constexpr uint64_t kSmallestBatch = uint64_t{1} << 14;

// One device's part: its frame, kernel, sums and counters, and what it traced.
struct PhotonWork {
    PhotonWork(const FrameScene& frame, size_t values)
        : frame(frame),
          kernel(frame.context.kernel("irradiance_vector_grid/irradiance_vector_grid.cl",
                                      "ivg_trace_photons")),
          accum(frame.context, values, "ivg_accum"),
          counters(frame.context, 2, "ivg_counters") {
        accum.fill_zero();
    }

    FrameScene frame;
    Kernel kernel;
    Buffer<int64_t> accum;
    Buffer<unsigned> counters;
    uint64_t photons = 0;
    uint64_t crossings = 0;
    uint64_t rays = 0;
};

}  // namespace

void IrradianceVectorGrid::trace_photons_split(uint64_t photons, Buffer<int64_t>& accum,
                                               IvgStats* stats) {
    std::vector<std::unique_ptr<PhotonWork>> works;
    works.push_back(std::make_unique<PhotonWork>(frame_, accum.size()));
    for (const FrameScene& peer : *frame_.peers) {
        works.push_back(std::make_unique<PhotonWork>(peer, accum.size()));
    }
    std::vector<Context*> contexts;
    for (const auto& work : works) {
        contexts.push_back(&work->frame.context);
    }
    const uint64_t batch = std::clamp(
        (photons + kBatchesPerDevice * works.size() - 1) / (kBatchesPerDevice * works.size()),
        kSmallestBatch, kLargestBatch);
    const size_t batches = static_cast<size_t>((photons + batch - 1) / batch);
    const DeviceSplit split = run_device_split(
        contexts, batches,
        [&](size_t device, size_t item, const std::atomic<bool>&) {
            PhotonWork& work = *works[device];
            const uint64_t first = item * batch;
            const uint64_t count = std::min(batch, photons - first);
            shared::IvgParams launch = params_;
            launch.first_photon = static_cast<unsigned>(first);
            work.counters.fill_zero();
            work.frame.context.launch(work.kernel, count, launch,
                                      SceneArguments(work.frame.bvh, work.frame.device_scene),
                                      work.accum, work.counters);
            const std::vector<unsigned> counted = work.counters.download();
            work.crossings += counted[0];
            work.rays += counted[1];
            work.photons += count;
        },
        {});
    // The devices' sums added (two's complement: exact and in any order).
    std::vector<int64_t> sums(accum.size(), 0);
    for (size_t d = 0; d < works.size(); ++d) {
        const PhotonWork& work = *works[d];
        const std::vector<int64_t> own = work.accum.download();
        for (size_t k = 0; k < sums.size(); ++k) {
            sums[k] = static_cast<int64_t>(static_cast<uint64_t>(sums[k]) +
                                           static_cast<uint64_t>(own[k]));
        }
        stats->crossings += work.crossings;
        stats->rays += work.rays;
        stats->devices.push_back(
            {work.frame.context.device().spec() + " " + work.frame.context.device().name,
             split.items[d].size(), work.photons, split.seconds[d]});
    }
    accum.upload(sums);
}

}  // namespace rc
