// A scene posed at each frame of its animation, on the device, each pose made on first use: the
// frames a test hands to a method that renders a clip (temporal caching's render_frame and its
// FrameHooks::visit_frame).
#pragma once

#include <map>
#include <memory>
#include <utility>

#include "test_support.h"

namespace rc::test {

class PosedFrames {
   public:
    explicit PosedFrames(Scene scene) : scene_(std::move(scene)) {}
    // The scene posed at `frame` (FrameScene::frame set).
    FrameScene at(int frame) {
        auto& slot = posed_[frame];
        if (!slot) {
            Scene s = scene_;
            s.set_frame(frame);
            slot = std::make_unique<DeviceFrame>(std::move(s));
        }
        FrameScene f = slot->frame();
        f.frame = frame;
        return f;
    }
    const Scene& scene() const { return scene_; }

   private:
    Scene scene_;
    std::map<int, std::unique_ptr<DeviceFrame>> posed_;
};

}  // namespace rc::test
