// Temporal caching's estimate of each new radiance record's value at the next frame (`--method rc
// --temporal`; the report's §4.3 applied to radiance caching's records, as its §3 and §6 do):
// shown every batch of records radiance caching computes (RadianceBatchObserver), it carries
// their uniform hemisphere cells to the next frame on the device (kernels/temporal/temporal.cl,
// the same carrying, depth test and 3 x 3 hole filling as irradiance records') and projects the
// result as a record's cells are projected: the record's SH coefficients and their gradients one
// frame later, from this frame's rays alone.
#pragma once

#include <vector>

#include "methods/frame_scene.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/temporal/tc_cells.h"
#include "methods/temporal/tc_motion.h"
#include "methods/temporal/temporal_glossy_record.h"

namespace rc {

// A radiance record's estimate at the next frame (its payload: radiance_records.h).
using CarriedRadianceRecord = CarriedGlossyRecord;

class TcRadianceReprojection final : public RadianceBatchObserver, private FrameBound {
   public:
    // Records of SH order `order` at `frame`, whose changes to the next frame are `motion`'s.
    TcRadianceReprojection(const FrameScene& frame, const TcMotion& motion, int order);

    void observe(const RadianceBatch& batch) override;

    // Every record observed so far, in observation order; clears the list.
    std::vector<CarriedRadianceRecord> take();

   private:
    const TcMotion& motion_;
    int order_;
    TcCellCarrier cells_;
    Kernel project_kernel_;
    std::vector<CarriedRadianceRecord> carried_;
};

}  // namespace rc
