// The geometry preview method: the first hit of every camera sample through the device BVH,
// shaded by its normal. What `radcache render --method normals` draws.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "methods/frame_scene.h"

namespace rc {

struct NormalsOptions {
    int width = 0;  // 0: the scene camera's resolution
    int height = 0;
    unsigned samples_per_pixel = 1;  // >1: jittered samples, averaged
    uint64_t seed = 0;
    // The first camera sample: the render draws samples first_sample .. first_sample +
    // samples_per_pixel - 1 of every pixel (a pass of a render by time), all jittered when
    // `jitter` (by default: unless it is one sample, then at the pixel's centre).
    unsigned first_sample = 0;
    enum class Jitter { kUnlessOneSample, kAlways } jitter = Jitter::kUnlessOneSample;
};

// One device's share of a preview on several devices.
struct NormalsDeviceShare {
    std::string device;  // "P:D name"
    size_t chunks = 0;   // chunks of rows it drew
    size_t pixels = 0;
    double seconds = 0.0;  // its thread's time
};

class NormalsMethod : private FrameBound {
   public:
    // With the frame's peers (several devices), the image's rows are drawn in chunks shared
    // among the devices (methods/device_split.h) and merged by chunk: bitwise the one-device
    // image on identical devices.
    explicit NormalsMethod(const FrameScene& frame);

    // `devices` (may be null): with peers, each device's share.
    Image render(const NormalsOptions& options, std::vector<NormalsDeviceShare>* devices = nullptr);

   private:
    std::vector<shared::float4> render_split(const NormalsOptions& options, int width, int height,
                                             std::vector<NormalsDeviceShare>* devices);

    FrameScene frame_;  // a copy: the caller's may be a temporary (its peers a pointer)
    Kernel kernel_;
};

}  // namespace rc
