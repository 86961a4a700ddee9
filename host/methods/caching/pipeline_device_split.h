// Irradiance caching on several devices (CachePipeline with the frame's peers): the
// records of a batch in ranges and the final pass (splat and render pass) in chunks of rows,
// shared among the devices (methods/device_split.h). A record's hemisphere sampling reads only its
// own site and random stream, so its payload does not depend on the device that computed it; the
// host gathers the payloads in record order and inserts them as with one device. Every device
// reads the same records, grid and splat tiles, made once on the host and uploaded to each. The
// image is bitwise the one-device image on identical devices, whatever the split.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "methods/caching/record_level_source.h"
#include "methods/caching/splat_tiles.h"
#include "methods/frame_scene.h"
#include "shared/radiance_cache.h"
#include "shared/types.h"

namespace rc {

// One device's share of an irradiance-cached frame.
struct PipelineDeviceShare {
    std::string device;           // "P:D name"
    size_t record_ranges = 0;     // record ranges (of the batches) it computed
    size_t records = 0;           // records it computed
    double record_seconds = 0.0;  // its threads' time over the batches
    size_t chunks = 0;            // chunks of rows of the final pass it rendered
    size_t pixels = 0;
    double final_seconds = 0.0;  // its thread's time in the final pass
};

// A batch of records to compute, as the host made it (batch order).
struct RecordBatchInput {
    const shared::IcParams& params;  // the records' level's kernel parameters
    const std::vector<shared::Record>& records;
    const std::vector<shared::float4>& origins;
    const std::vector<unsigned>& streams;
};

// What the kernels computed for a batch, in batch order.
struct RecordBatchOutput {
    std::vector<shared::IrradiancePayload> payloads;
    std::vector<shared::float4> distances;  // (harmonic mean, minimum) hit distance
    uint64_t rays = 0;
};

// What the final pass reads: the first level's records and their splat over the camera samples.
struct FinalPassInput {
    shared::IcParams splat_params;  // candidates: every camera sample (entry pixel * spp + s)
    shared::IcParams shade_params;  // the render pass's
    const shared::CameraParams& camera;
    const HostRecords& records;  // with the grid when the records overlay is drawn
    const SplatTiles& tiles;
    const Buffer<shared::GBufferSample>& gbuffer;  // the camera samples, on the first device
    // The glossy lobes' cache at the camera samples (radiance caching), on the first device; one
    // zero entry when none serves them.
    const Buffer<shared::RcGlossySample>& glossy;
    int width = 0;
    int height = 0;
    int spp = 1;
};

// The render pass's film sums (RC_CACHED_FILM_SLOTS per pixel) and counters.
struct FinalPassOutput {
    std::vector<shared::float4> film;
    uint64_t rays = 0;
    uint64_t nonfinite_samples = 0;
    int64_t first_nonfinite_pixel = -1;
    size_t cache_bytes = 0;  // on the first device: records, payloads, grid, splat buffer
};

class PipelineDeviceSplit {
   public:
    // The frame's device and its peers (frame.peers: not empty).
    explicit PipelineDeviceSplit(const FrameScene& frame);
    ~PipelineDeviceSplit();

    // The batch's hemisphere sampling (ic_record_cells, ic_record_reduce) in record ranges: the
    // radiance beyond the hits read from `next_level`'s records (null: path-traced continuation).
    RecordBatchOutput compute_batch(const RecordBatchInput& batch, const HostRecords* next_level);
    // The splat buffer and the render pass in chunks of rows; the film merged by chunk.
    FinalPassOutput final_pass(const FinalPassInput& input);

    const std::vector<PipelineDeviceShare>& shares() const { return shares_; }

   private:
    struct Device;
    std::vector<std::unique_ptr<Device>> devices_;
    std::vector<PipelineDeviceShare> shares_;
    // Each device's records per second in the last batch it computed records of (0: none yet):
    // the next batch's split does not wait on a slow device (run_device_split).
    std::vector<double> record_speeds_;
};

}  // namespace rc
