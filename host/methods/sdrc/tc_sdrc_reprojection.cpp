#include "methods/sdrc/tc_sdrc_reprojection.h"

#include <string>

#include "methods/scene_arguments.h"

namespace rc {

TcSdrcReprojection::TcSdrcReprojection(const FrameScene& frame, const TcMotion& motion)
    : FrameBound(frame), motion_(motion), cells_(frame) {}

void TcSdrcReprojection::observe(const SdrcBatch& batch) {
    const int m = kSdrcTemporalRows;
    const int n = kSdrcTemporalColumns;
    const size_t samples = static_cast<size_t>(batch.params.samples);
    Kernel next_kernel =
        context_.kernel("sdrc/sdrc_trace.cl", "sdrc_record_next", batch.diffuse.build_options());
    // Step 1: the records' uniform cells (traced by the record kernel) carried to the next frame.
    const Buffer<shared::float4> next_cells = cells_.next_glossy_cells(
        motion_, m, n, batch.params.seed_lo ^ RC_SDRC_CELL_DOMAIN, batch.params.seed_hi,
        batch.site_values, batch.streams, batch.cells, batch.count);
    // Step 2: every sample's radiance moved by its cell's change.
    Buffer<shared::float4> next(context_, batch.count * samples, "tc_sdrc_next");
    context_.launch(next_kernel, batch.count * samples, batch.params, m, n, device_scene_.materials,
                    batch.sites, batch.streams, batch.samples, batch.cells, next_cells, next);
    const std::vector<shared::float4> now = batch.samples.download();
    const std::vector<shared::float4> later = next.download();
    const std::vector<shared::LTreeNode> nodes = batch.nodes.download();
    for (size_t b = 0; b < batch.count; ++b) {
        CarriedSdrcRecord r;
        r.carried.site = batch.site_values[b];
        r.carried.stream = batch.stream_values[b];
        r.carried.site_moves = motion_.primitive_moves(r.carried.site.primitive);
        r.payload.resize(3 * samples);
        r.carried.next.resize(3 * samples);
        for (size_t k = 0; k < samples; ++k) {
            const shared::float4& l0 = now[b * samples + k];
            const shared::float4& l1 = later[b * samples + k];
            r.payload[k] = l0.x;
            r.payload[samples + k] = l0.y;
            r.payload[2 * samples + k] = l0.z;
            r.carried.next[k] = l1.x;
            r.carried.next[samples + k] = l1.y;
            r.carried.next[2 * samples + k] = l1.z;
        }
        r.nodes.assign(nodes.begin() + static_cast<long>(b * samples),
                       nodes.begin() + static_cast<long>((b + 1) * samples));
        carried_.push_back(std::move(r));
    }
}

std::vector<CarriedSdrcRecord> TcSdrcReprojection::take() {
    std::vector<CarriedSdrcRecord> taken;
    taken.swap(carried_);
    return taken;
}

}  // namespace rc
