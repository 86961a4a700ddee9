#include "methods/temporal/tc_reprojection.h"

#include "methods/scene_arguments.h"
#include "util/timing.h"

namespace rc {

TemporalReprojection::TemporalReprojection(const FrameScene& frame, const Scene& next,
                                           int hole_passes)
    : FrameBound(frame),
      motion_(frame.context, frame.scene, next, frame.frame, hole_passes),
      carry_kernel_(frame.context.kernel("temporal/temporal.cl", "tc_carry_cells")),
      assemble_kernel_(frame.context.kernel("temporal/temporal.cl", "tc_assemble_cells")),
      reduce_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_record_reduce")) {}

void TemporalReprojection::observe(const RecordBatch& batch) {
    const auto start = SteadyClock::now();
    const size_t per_record = static_cast<size_t>(batch.params.strata_m) * batch.params.strata_n;
    const size_t cells = batch.count * per_record;
    Buffer<shared::TcCarriedSample> carried(context_, cells, "tc_carried");
    const shared::TcParams params = motion_.params(RC_TC_CELLS_COSINE);
    context_.launch(carry_kernel_, cells, batch.params, params, SceneArguments(bvh_, device_scene_),
                    batch.records, batch.origins, batch.streams, batch.cells, motion_.moved_slot(),
                    motion_.moved_triangles(), motion_.emitters_now(), motion_.emitters_next(),
                    carried);
    Buffer<shared::float4> next_cells(context_, cells, "tc_next_cells");
    Buffer<unsigned> marks(context_, cells, "tc_marks");
    context_.launch(assemble_kernel_, batch.count, batch.params, params, batch.streams, carried,
                    batch.cells, next_cells, marks);
    Buffer<shared::IrradiancePayload> payloads(context_, batch.count, "tc_next_payloads");
    Buffer<shared::float4> distances(context_, batch.count, "tc_next_distances");
    context_.launch(reduce_kernel_, batch.count, batch.params, next_cells, batch.records,
                    batch.streams, payloads, distances);
    const std::vector<shared::IrradiancePayload> next = payloads.download();
    for (size_t b = 0; b < batch.count; ++b) {
        CarriedRecord r;
        r.site = batch.sites[b];
        r.site.stream = static_cast<int64_t>(batch.stream_values[b]);
        r.next = next[b];
        r.site_moves = motion_.primitive_moves(batch.sites[b].primitive);
        carried_[batch.params.level].push_back(r);
    }
    seconds_ += seconds_since(start);
}

std::vector<CarriedRecord> TemporalReprojection::take(int level) {
    std::vector<CarriedRecord> taken;
    taken.swap(carried_[level]);
    return taken;
}

}  // namespace rc
