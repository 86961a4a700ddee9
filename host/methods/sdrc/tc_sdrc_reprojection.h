// Temporal caching's estimate of each new SDRC record's value at the next frame (`--method sdrc
// --temporal`; the report's §4.3 applied to SDRC's records, as its §3 applies it to any cached
// payload): shown every batch of records SdrcCache computes (SdrcBatchObserver), with each
// record's hemisphere sampled on uniform cells by the record kernel (sdrc_record_samples: the
// L-tree's lobe-sampled directions fall in no cell grid), it carries the cells to the next frame
// with temporal caching's one carry kernel (TcCellCarrier: the same carrying, depth test and 3 x 3
// hole filling as irradiance and radiance records'), and moves each L-tree sample's radiance by the
// change of the cell its direction passes through (sdrc_record_next). The payload is the samples'
// radiance, channel by channel in sample order, as the record kernel drew them.
#pragma once

#include <cstdint>
#include <vector>

#include "methods/frame_scene.h"
#include "methods/sdrc/sdrc_cache.h"
#include "methods/temporal/tc_cells.h"
#include "methods/temporal/tc_motion.h"
#include "methods/temporal/temporal_glossy_record.h"

namespace rc {

// Uniform hemisphere cells per SDRC record for the reprojection (rows x columns, N ~ 4 M as
// radiance caching's strata).
inline constexpr int kSdrcTemporalRows = 8;
inline constexpr int kSdrcTemporalColumns = 32;

// A new SDRC record as temporal caching keeps it: its estimate at the next frame, its payload
// (the samples' radiance: r of every sample, then g, then b) and its samples' L-tree nodes in
// sample order (the tree is built from them at every frame).
struct CarriedSdrcRecord {
    CarriedGlossyRecord carried;
    std::vector<float> payload;
    std::vector<shared::LTreeNode> nodes;
};

class TcSdrcReprojection final : public SdrcBatchObserver, private FrameBound {
   public:
    // Records at `frame`, whose changes to the next frame are `motion`'s.
    TcSdrcReprojection(const FrameScene& frame, const TcMotion& motion);

    int cell_rows() const override { return kSdrcTemporalRows; }
    int cell_columns() const override { return kSdrcTemporalColumns; }
    void observe(const SdrcBatch& batch) override;

    // Every record observed so far, in observation order; clears the list.
    std::vector<CarriedSdrcRecord> take();

   private:
    const TcMotion& motion_;
    TcCellCarrier cells_;
    std::vector<CarriedSdrcRecord> carried_;
};

}  // namespace rc
