// What changes between a frame and the next as temporal caching's reprojection sees it (the
// report's §4.3: "the changes between times t0 and t0 + 1 are known"): which triangles move and
// where they go, and the emitters at both frames, on the device for the reprojection kernels
// (kernels/temporal/), whatever records they carry (TemporalReprojection for irradiance records,
// TcRadianceReprojection for radiance records).
#pragma once

#include <cstdint>
#include <vector>

#include "device/buffer.h"
#include "device/context.h"
#include "scene/scene.h"
#include "shared/temporal.h"

namespace rc {

class TcMotion {
   public:
    // `now` posed at frame `frame`, `next` the same scene posed at the next frame; `hole_passes`
    // of the reprojection's hole filling. Error when the two differ in triangles or emitters.
    TcMotion(Context& context, const Scene& now, const Scene& next, int frame, int hole_passes);

    // The reprojection kernels' parameters for hemisphere cells of `cell_layout`.
    shared::TcParams params(int cell_layout) const;
    // Per primitive: 1 where it moves between the two frames.
    const std::vector<uint8_t>& moves() const { return moves_; }
    size_t moving_primitives() const { return moving_; }
    // Whether any emitter differs between the two frames.
    bool emitters_change() const { return params_.emitters_change != 0; }
    bool primitive_moves(int primitive) const {
        return primitive >= 0 && static_cast<size_t>(primitive) < moves_.size() &&
               moves_[static_cast<size_t>(primitive)] != 0;
    }

    const Buffer<int>& moved_slot() const { return moved_slot_; }
    const Buffer<shared::Triangle>& moved_triangles() const { return moved_triangles_; }
    const Buffer<shared::TcEmitter>& emitters_now() const { return emitters_now_; }
    const Buffer<shared::TcEmitter>& emitters_next() const { return emitters_next_; }

   private:
    shared::TcParams params_{};
    std::vector<uint8_t> moves_;
    size_t moving_ = 0;
    Buffer<int> moved_slot_;
    Buffer<shared::Triangle> moved_triangles_;
    Buffer<shared::TcEmitter> emitters_now_;
    Buffer<shared::TcEmitter> emitters_next_;
};

}  // namespace rc
