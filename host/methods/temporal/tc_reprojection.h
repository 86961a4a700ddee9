// Temporal caching's estimate of each new record's value at the next frame (the report's §4.3, §5
// "Reprojection of Incoming Radiance"): shown every batch of first-level records irradiance
// caching computes at any cache level (RecordBatchObserver), it carries their hemisphere samples to
// the next frame on the device (kernels/temporal/temporal.cl: the hit points moved with their
// triangles, the radiance with the change of the unshadowed light, a depth test and 3 x 3 hole
// filling) and reduces the result as a record's cells are reduced: the record's irradiance and
// gradients one frame later, from this frame's rays alone.
#pragma once

#include <map>
#include <vector>

#include "device/buffer.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/frame_scene.h"
#include "methods/temporal/tc_cells.h"
#include "methods/temporal/tc_motion.h"
#include "shared/temporal.h"

namespace rc {

// A record's estimate at the next frame.
struct CarriedRecord {
    RecordSite site;                   // where it was computed
    shared::IrradiancePayload next{};  // irradiance and gradients estimated one frame later
    bool site_moves = false;           // the triangle the record lies on moves by then
};

class TemporalReprojection final : public RecordBatchObserver, private FrameBound {
   public:
    // This frame `frame`; `next`: the same scene posed at the next frame.
    TemporalReprojection(const FrameScene& frame, const Scene& next, int hole_passes);

    void observe(const RecordBatch& batch) override;

    // Every record of cache level `level` observed so far, in observation order; clears the list.
    std::vector<CarriedRecord> take(int level);

    // Seconds spent in observe() so far (the reprojection's kernels and the download).
    double seconds() const { return seconds_; }

    // What moves and changes between the two frames.
    const TcMotion& motion() const { return motion_; }
    // Primitives that move between the two frames.
    size_t moving_primitives() const { return motion_.moving_primitives(); }
    // Per primitive: 1 where it moves between the two frames.
    const std::vector<uint8_t>& moves() const { return motion_.moves(); }
    // Nothing moves and no emitter changes between the two frames (the camera may move).
    bool still() const { return moving_primitives() == 0 && !motion_.emitters_change(); }

   private:
    TcMotion motion_;
    TcCellCarrier cells_;
    Kernel reduce_kernel_;
    std::map<int, std::vector<CarriedRecord>> carried_;  // by level
    double seconds_ = 0.0;
};

}  // namespace rc
