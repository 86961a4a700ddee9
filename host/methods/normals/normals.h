// The geometry preview method: the first hit of every camera sample through the device BVH,
// shaded by its normal. What `radcache render --method normals` draws.
#pragma once

#include <cstdint>

#include "bvh/device_bvh.h"
#include "device/context.h"
#include "image/image.h"
#include "scene/scene.h"

namespace rc {

struct NormalsOptions {
    int width = 0;  // 0: the scene camera's resolution
    int height = 0;
    unsigned samples_per_pixel = 1;  // >1: jittered samples, averaged
    uint64_t seed = 0;
};

class NormalsMethod {
   public:
    NormalsMethod(Context& context, const Scene& scene, const DeviceBvh& bvh);

    Image render(const NormalsOptions& options);

   private:
    Context& context_;
    const Scene& scene_;
    const DeviceBvh& bvh_;
    Kernel kernel_;
};

}  // namespace rc
