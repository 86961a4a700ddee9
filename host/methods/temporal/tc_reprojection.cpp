#include "methods/temporal/tc_reprojection.h"

#include "methods/scene_arguments.h"
#include "util/timing.h"

namespace rc {

TemporalReprojection::TemporalReprojection(const FrameScene& frame, const Scene& next,
                                           int hole_passes)
    : FrameBound(frame),
      motion_(frame.context, frame.scene, next, frame.frame, hole_passes),
      cells_(frame),
      reduce_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_record_reduce")) {}

void TemporalReprojection::observe(const RecordBatch& batch) {
    const auto start = SteadyClock::now();
    // The records' frames (their normals), with no cell below the surface: irradiance caching's
    // cosine-weighted cells all lie above the record's plane.
    std::vector<shared::float4> normal_values(batch.count);
    for (size_t b = 0; b < batch.count; ++b) {
        normal_values[b] = batch.record_values[b].normal;
        normal_values[b].w = 0.0f;
    }
    const Buffer<shared::float4> normals(context_, normal_values, "tc_normals");
    const Buffer<shared::float4> next_cells = cells_.next_cells(
        motion_, {RC_TC_CELLS_COSINE, batch.params.strata_m, batch.params.strata_n,
                  batch.params.seed_lo ^ RC_IC_RNG_DOMAIN,
                  batch.params.seed_hi ^ (static_cast<unsigned>(batch.params.level) * 0x9e3779b9u),
                  batch.origins, normals, normals, batch.streams, batch.cells, batch.count});
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
