// The devices of one render: `--device all` or a comma-separated list opens one
// context per device; the first serves every method, the others (the peers) only a method that
// splits its frames' work across devices (Method::splits_across_devices), which gets each frame's
// scene and BVH on every peer (PeerFrames).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "device/context.h"
#include "methods/frame_scene.h"
#include "methods/method.h"
#include "scene/device_scene.h"

namespace rc {

// One context per device `options.device_spec` names (device/device_list.h, select_devices),
// each with `method`'s programs started building. Error (exit status 2) when it names several
// and method `name` renders on one.
std::vector<std::unique_ptr<Context>> open_render_devices(const ContextOptions& options,
                                                          const Method& method,
                                                          const std::string& name);

// A frame's scene and BVH on the peer devices (contexts 1, 2, ... of a render).
class PeerFrames {
   public:
    // `bvh` is the first device's BVH of `scene` (reused where a peer takes the same layout).
    PeerFrames(const std::vector<std::unique_ptr<Context>>& contexts, const Scene& scene,
               const Bvh& bvh, int frame);
    const std::vector<FrameScene>& frames() const { return frames_; }

   private:
    std::vector<std::unique_ptr<Bvh>> bvhs_;
    std::vector<std::unique_ptr<DeviceBvh>> device_bvhs_;
    std::vector<std::unique_ptr<DeviceScene>> device_scenes_;
    std::vector<FrameScene> frames_;
};

}  // namespace rc
