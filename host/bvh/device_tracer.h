// Batches of rays traced on the device: closest hit, any hit, and the rays the benchmark and
// the tests trace (camera rays, diffuse bounces). Schedules the kernels of trace.cl and
// spawn_rays.cl.
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/device_bvh.h"
#include "device/context.h"
#include "shared/types.h"

namespace rc {

class DeviceTracer {
   public:
    DeviceTracer(Context& context, const DeviceBvh& bvh);

    std::vector<shared::Hit> trace_closest(const std::vector<shared::Ray>& rays);
    std::vector<unsigned> trace_any(const std::vector<shared::Ray>& rays);

    // The same on rays already on the device (benchmarks: no transfers in the timed part).
    void trace_closest(const Buffer<shared::Ray>& rays, Buffer<shared::Hit>& hits);
    void trace_any(const Buffer<shared::Ray>& rays, Buffer<unsigned>& occluded);

    // One centred ray per pixel, row-major from the top-left pixel.
    std::vector<shared::Ray> camera_rays(const shared::CameraParams& camera);
    // A cosine-distributed bounce from the closest hit of each ray; rays that miss give rays
    // with zero direction, which `traceable_only` removes.
    std::vector<shared::Ray> diffuse_bounce_rays(const std::vector<shared::Ray>& rays,
                                                 uint64_t seed, bool traceable_only = true);

   private:
    Context& context_;
    const DeviceBvh& bvh_;
    Kernel closest_;
    Kernel any_;
    Kernel camera_;
    Kernel bounce_;
};

}  // namespace rc
