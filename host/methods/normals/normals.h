// The geometry preview method: the first hit of every camera sample through the device BVH,
// shaded by its normal. What `radcache render --method normals` draws.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "methods/frame_scene.h"

namespace rc {

struct NormalsOptions {
    int width = 0;  // 0: the scene camera's resolution
    int height = 0;
    unsigned samples_per_pixel = 1;  // >1: jittered samples, averaged
    uint64_t seed = 0;
};

class NormalsMethod : private FrameBound {
   public:
    explicit NormalsMethod(const FrameScene& frame);

    Image render(const NormalsOptions& options);

   private:
    Kernel kernel_;
};

}  // namespace rc
