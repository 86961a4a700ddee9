#include "methods/temporal/tc_reprojection.h"

#include <cstring>
#include <glm/common.hpp>
#include <limits>

#include "methods/scene_arguments.h"
#include "methods/temporal/tc_emitters.h"
#include "util/error.h"
#include "util/glm_helpers.h"

namespace rc {
namespace {

// The world triangle of primitive p of a posed scene.
shared::Triangle world_triangle(const Scene& scene, size_t p) {
    const glm::uvec3 v = scene.mesh.triangles[p];
    return {float4_of(scene.mesh.positions[v.x]), float4_of(scene.mesh.positions[v.y]),
            float4_of(scene.mesh.positions[v.z])};
}

bool same_triangle(const Scene& a, const Scene& b, size_t p) {
    const glm::uvec3 va = a.mesh.triangles[p];
    const glm::uvec3 vb = b.mesh.triangles[p];
    for (int i = 0; i < 3; ++i) {
        if (a.mesh.positions[va[i]] != b.mesh.positions[vb[i]]) {
            return false;
        }
    }
    return true;
}

}  // namespace

TemporalReprojection::TemporalReprojection(const FrameScene& frame, const Scene& next,
                                           int hole_passes)
    : FrameBound(frame),
      carry_kernel_(frame.context.kernel("temporal/temporal.cl", "tc_carry_cells")),
      assemble_kernel_(frame.context.kernel("temporal/temporal.cl", "tc_assemble_cells")),
      reduce_kernel_(
          frame.context.kernel("irradiance_cache/irradiance_cache.cl", "ic_record_reduce")) {
    const Scene& now = frame.scene;
    if (now.mesh.triangles.size() != next.mesh.triangles.size()) {
        throw Error("temporal caching: the scene has " + std::to_string(now.mesh.triangles.size()) +
                    " triangles at frame " + std::to_string(frame.frame) + " and " +
                    std::to_string(next.mesh.triangles.size()) + " at the next");
    }
    // The primitives that move, and their next world triangles.
    std::vector<int> slots(now.mesh.triangles.size(), -1);
    std::vector<shared::Triangle> moved;
    moves_.assign(slots.size(), 0);
    glm::vec3 lower(std::numeric_limits<float>::infinity());
    glm::vec3 upper(-std::numeric_limits<float>::infinity());
    for (size_t p = 0; p < slots.size(); ++p) {
        if (!same_triangle(now, next, p)) {
            slots[p] = static_cast<int>(moved.size());
            moved.push_back(world_triangle(next, p));
            moves_[p] = 1;
            const glm::uvec3 v = now.mesh.triangles[p];
            for (int i = 0; i < 3; ++i) {
                lower = glm::min(lower, now.mesh.positions[v[i]]);
                upper = glm::max(upper, now.mesh.positions[v[i]]);
            }
        }
    }
    params_.moving_lower = float4_of(lower);
    params_.moving_upper = float4_of(upper);
    moving_ = moved.size();
    moved_slot_ = Buffer<int>(context_, slots, "tc_moved_slot");
    moved_triangles_ = Buffer<shared::Triangle>(context_, moved, "tc_moved_triangles");
    const std::vector<shared::TcEmitter> emitters_now = unshadowed_emitters(now);
    const std::vector<shared::TcEmitter> emitters_next = unshadowed_emitters(next);
    if (emitters_now.size() != emitters_next.size()) {
        throw Error("temporal caching: the emitters differ between frame " +
                    std::to_string(frame.frame) + " and the next");
    }
    emitters_now_ = Buffer<shared::TcEmitter>(context_, emitters_now, "tc_emitters_now");
    emitters_next_ = Buffer<shared::TcEmitter>(context_, emitters_next, "tc_emitters_next");
    params_.emitter_count = static_cast<int>(emitters_now.size());
    params_.emitters_change =
        emitters_now.empty() ? 0
                             : std::memcmp(emitters_now.data(), emitters_next.data(),
                                           emitters_now.size() * sizeof(shared::TcEmitter)) != 0;
    params_.hole_passes = hole_passes;
}

void TemporalReprojection::observe(const RecordBatch& batch) {
    const size_t per_record = static_cast<size_t>(batch.params.strata_m) * batch.params.strata_n;
    const size_t cells = batch.count * per_record;
    Buffer<shared::TcCarriedSample> carried(context_, cells, "tc_carried");
    context_.launch(carry_kernel_, cells, batch.params, params_,
                    SceneArguments(bvh_, device_scene_), batch.records, batch.origins,
                    batch.streams, batch.cells, moved_slot_, moved_triangles_, emitters_now_,
                    emitters_next_, carried);
    Buffer<shared::float4> next_cells(context_, cells, "tc_next_cells");
    Buffer<unsigned> marks(context_, cells, "tc_marks");
    context_.launch(assemble_kernel_, batch.count, batch.params, params_, batch.streams, carried,
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
        const int primitive = batch.sites[b].primitive;
        r.site_moves = primitive >= 0 && static_cast<size_t>(primitive) < moves_.size() &&
                       moves_[static_cast<size_t>(primitive)] != 0;
        carried_[batch.params.level].push_back(r);
    }
}

std::vector<CarriedRecord> TemporalReprojection::take(int level) {
    std::vector<CarriedRecord> taken;
    taken.swap(carried_[level]);
    return taken;
}

}  // namespace rc
