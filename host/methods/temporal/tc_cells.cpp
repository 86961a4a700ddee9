#include "methods/temporal/tc_cells.h"

#include <vector>

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

Buffer<shared::float4> TcCellCarrier::next_glossy_cells(
    const TcMotion& motion, int strata_m, int strata_n, unsigned key_lo, unsigned key_hi,
    const shared::RcQuery* sites, const Buffer<unsigned>& streams,
    const Buffer<shared::float4>& cells, size_t count) {
    std::vector<shared::float4> origins(count), normals(count), surfaces(count);
    for (size_t b = 0; b < count; ++b) {
        origins[b] = sites[b].origin;
        normals[b] = sites[b].normal;
        surfaces[b] = sites[b].geometric_normal;
        surfaces[b].w = 1.0f;
    }
    const Buffer<shared::float4> origin_buffer(context_, origins, "tc_glossy_origins");
    const Buffer<shared::float4> normal_buffer(context_, normals, "tc_glossy_normals");
    const Buffer<shared::float4> surface_buffer(context_, surfaces, "tc_glossy_surfaces");
    return next_cells(motion,
                      {RC_TC_CELLS_UNIFORM, strata_m, strata_n, key_lo, key_hi, origin_buffer,
                       normal_buffer, surface_buffer, streams, cells, count});
}

}  // namespace rc
