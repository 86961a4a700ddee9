#include "methods/radiance_cache/tc_radiance_reprojection.h"

#include "methods/radiance_cache/radiance_records.h"
#include "methods/scene_arguments.h"

namespace rc {

TcRadianceReprojection::TcRadianceReprojection(const FrameScene& frame, const TcMotion& motion,
                                               int order)
    : FrameBound(frame),
      motion_(motion),
      order_(order),
      cells_(frame),
      project_kernel_(frame.context.kernel("radiance_cache/rc_cache.cl", "rc_record_project")) {}

void TcRadianceReprojection::observe(const RadianceBatch& batch) {
    // The records' uniform cells carried to the next frame (their frames: the sites' shading
    // normals; a cell below the surface traced no ray, rc_record_cells), with the key of the
    // records' streams (rc_record_key).
    const Buffer<shared::float4> next_cells =
        cells_.next_glossy_cells(motion_, batch.params.strata_m, batch.params.strata_n,
                                 batch.params.seed_lo ^ RC_RC_RNG_DOMAIN, batch.params.seed_hi,
                                 batch.site_values, batch.streams, batch.cells, batch.count);
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
