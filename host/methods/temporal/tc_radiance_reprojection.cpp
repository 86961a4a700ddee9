#include "methods/temporal/tc_radiance_reprojection.h"

#include "methods/radiance_cache/radiance_records.h"
#include "methods/scene_arguments.h"

namespace rc {

TcRadianceReprojection::TcRadianceReprojection(const FrameScene& frame, const TcMotion& motion,
                                               int order)
    : FrameBound(frame),
      motion_(motion),
      order_(order),
      carry_kernel_(frame.context.kernel("temporal/tc_radiance.cl", "tc_carry_radiance_cells")),
      assemble_kernel_(
          frame.context.kernel("temporal/tc_radiance.cl", "tc_assemble_radiance_cells")),
      project_kernel_(frame.context.kernel("radiance_cache/rc_cache.cl", "rc_record_project")) {}

void TcRadianceReprojection::observe(const RadianceBatch& batch) {
    const size_t per_record = static_cast<size_t>(batch.params.strata_m) * batch.params.strata_n;
    const size_t cells = batch.count * per_record;
    const shared::TcParams params = motion_.params(RC_TC_CELLS_UNIFORM);
    Buffer<shared::TcCarriedSample> carried(context_, cells, "tc_radiance_carried");
    context_.launch(carry_kernel_, cells, batch.params, params, SceneArguments(bvh_, device_scene_),
                    batch.sites, batch.streams, batch.cells, motion_.moved_slot(),
                    motion_.moved_triangles(), motion_.emitters_now(), motion_.emitters_next(),
                    carried);
    Buffer<shared::float4> next_cells(context_, cells, "tc_radiance_next_cells");
    Buffer<unsigned> marks(context_, cells, "tc_radiance_marks");
    context_.launch(assemble_kernel_, batch.count, batch.params, params, batch.streams, carried,
                    batch.cells, next_cells, marks);
    const size_t floats = radiance_payload_floats(order_);
    Buffer<float> payloads(context_, batch.count * floats, "tc_radiance_next_payloads");
    Buffer<shared::float4> distances(context_, batch.count, "tc_radiance_next_distances");
    context_.launch(project_kernel_, batch.count, batch.params, batch.streams, next_cells, payloads,
                    distances);
    const std::vector<float> next = payloads.download();
    for (size_t b = 0; b < batch.count; ++b) {
        CarriedRadianceRecord r;
        r.site = batch.site_values[b];
        r.stream = batch.stream_values[b];
        r.next.assign(next.begin() + static_cast<long>(b * floats),
                      next.begin() + static_cast<long>((b + 1) * floats));
        r.site_moves = motion_.primitive_moves(r.site.primitive);
        carried_.push_back(std::move(r));
    }
}

std::vector<CarriedRadianceRecord> TcRadianceReprojection::take() {
    std::vector<CarriedRadianceRecord> taken;
    taken.swap(carried_);
    return taken;
}

}  // namespace rc
