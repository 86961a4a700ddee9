#include "methods/temporal/tc_cells.h"

#include "methods/scene_arguments.h"

namespace rc {

TcCellCarrier::TcCellCarrier(const FrameScene& frame)
    : FrameBound(frame),
      carry_kernel_(frame.context.kernel("temporal/temporal.cl", "tc_carry_cells")),
      assemble_kernel_(frame.context.kernel("temporal/temporal.cl", "tc_assemble_cells")) {}

Buffer<shared::float4> TcCellCarrier::next_cells(const TcMotion& motion, const TcCellBatch& batch) {
    shared::TcParams params = motion.params(batch.cell_layout);
    params.strata_m = batch.strata_m;
    params.strata_n = batch.strata_n;
    params.key_lo = batch.key_lo;
    params.key_hi = batch.key_hi;
    const size_t cells = batch.count * static_cast<size_t>(batch.strata_m) * batch.strata_n;
    // Step 1: every cell's sample carried to the next frame.
    Buffer<shared::TcCarriedSample> carried(context_, cells, "tc_carried");
    context_.launch(carry_kernel_, cells, params, SceneArguments(bvh_, device_scene_),
                    batch.origins, batch.normals, batch.surfaces, batch.streams, batch.cells,
                    motion.moved_slot(), motion.moved_triangles(), motion.emitters_now(),
                    motion.emitters_next(), carried);
    // Step 2: each record's carried samples put back into its cells (depth test, holes filled).
    Buffer<shared::float4> next(context_, cells, "tc_next_cells");
    Buffer<unsigned> marks(context_, cells, "tc_marks");
    context_.launch(assemble_kernel_, batch.count, params, batch.streams, carried, batch.cells,
                    next, marks);
    return next;
}

}  // namespace rc
