// One frame as a method sees it — the device, the scene posed at the frame, its BVH and scene
// buffers on the device (rebuilt every frame) — and FrameBound, the base of the classes that
// schedule a method's kernels for one frame and keep those four references.
#pragma once

#include "bvh/device_bvh.h"
#include "device/context.h"
#include "scene/device_scene.h"
#include "scene/scene.h"

namespace rc {

struct FrameScene {
    Context& context;
    const Scene& scene;
    const DeviceBvh& bvh;
    const DeviceScene& device_scene;
    int frame = 0;
};

class FrameBound {
   protected:
    explicit FrameBound(const FrameScene& frame)
        : context_(frame.context),
          scene_(frame.scene),
          bvh_(frame.bvh),
          device_scene_(frame.device_scene) {}

    Context& context_;
    const Scene& scene_;
    const DeviceBvh& bvh_;
    const DeviceScene& device_scene_;
};

}  // namespace rc
