// One frame as a method sees it — the device, the scene posed at the frame, its BVH and scene
// buffers on the device (rebuilt every frame) — and FrameBound, the base of the classes that
// schedule a method's kernels for one frame and keep those four references.
#pragma once

#include <vector>

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
    // The same frame on the render's other devices (--device with several), each with its own
    // BVH and scene buffers; empty or null with one device. Only a method that splits its work
    // across devices (Method::splits_across_devices) is given them.
    const std::vector<FrameScene>* peers = nullptr;
};

// The devices `frame` renders on: its own and its peers.
inline size_t frame_devices(const FrameScene& frame) {
    return 1 + (frame.peers != nullptr ? frame.peers->size() : 0);
}

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
