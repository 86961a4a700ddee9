// The scene's buffers passed to a kernel as one argument group, in the order of
// kernels/scene_arguments.h (RC_SCENE_PARAMETERS).
#pragma once

#include "bvh/device_bvh.h"
#include "device/kernel.h"
#include "scene/device_scene.h"

namespace rc {

class SceneArguments : public KernelArgumentGroup {
   public:
    SceneArguments(const DeviceBvh& bvh, const DeviceScene& scene) : bvh_(bvh), scene_(scene) {}
    unsigned set_kernel_args(Kernel& kernel, unsigned first) const override;

   private:
    const DeviceBvh& bvh_;
    const DeviceScene& scene_;
};

}  // namespace rc
