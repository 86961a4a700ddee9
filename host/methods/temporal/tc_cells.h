// Temporal caching's reprojection of a batch of records' hemisphere cells to the next frame (the
// report's §4.3), whatever payload the records reduce their cells to: the cells' samples carried
// with the motion and the light's change, then put back into each record's cells with a depth test
// and hole filling (kernels/temporal/temporal.cl). TemporalReprojection (irradiance records) and
// TcRadianceReprojection (radiance records) then reduce the assembled cells as their records'
// own cells are reduced.
#pragma once

#include <cstddef>

#include "device/buffer.h"
#include "device/kernel.h"
#include "methods/frame_scene.h"
#include "methods/temporal/tc_motion.h"
#include "shared/radiance_cache.h"

namespace rc {

// A batch of `count` records' hemisphere cells as the record kernels left them on the device.
struct TcCellBatch {
    int cell_layout;  // RC_TC_CELLS_COSINE (irradiance records) or RC_TC_CELLS_UNIFORM (radiance)
    int strata_m;     // M x N cells per record
    int strata_n;
    unsigned key_lo;  // the key of the records' random streams (the cells' jitter)
    unsigned key_hi;
    const Buffer<shared::float4>& origins;   // where each record's rays leave
    const Buffer<shared::float4>& normals;   // xyz: the normal of each record's frame
    const Buffer<shared::float4>& surfaces;  // w 1: cells below the plane of xyz traced no ray
    const Buffer<unsigned>& streams;         // each record's random stream
    const Buffer<shared::float4>& cells;     // count x M N cells: (L.rgb, hit distance)
    size_t count;
};

class TcCellCarrier : private FrameBound {
   public:
    explicit TcCellCarrier(const FrameScene& frame);

    // The batch's cells as the next frame is estimated to show them (`motion`: the changes to it).
    Buffer<shared::float4> next_cells(const TcMotion& motion, const TcCellBatch& batch);
    // The same for a glossy cache's records at `sites` (`count` host copies) on M x N uniform
    // cells (RC_TC_CELLS_UNIFORM) jittered by streams of key (key_lo, key_hi): each record's
    // frame is its site's shading normal, and its cells below the site's own surface traced no
    // ray.
    Buffer<shared::float4> next_glossy_cells(const TcMotion& motion, int strata_m, int strata_n,
                                             unsigned key_lo, unsigned key_hi,
                                             const shared::RcQuery* sites,
                                             const Buffer<unsigned>& streams,
                                             const Buffer<shared::float4>& cells, size_t count);

   private:
    Kernel carry_kernel_;
    Kernel assemble_kernel_;
};

}  // namespace rc
