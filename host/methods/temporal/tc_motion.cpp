#include "methods/temporal/tc_motion.h"

#include <cstring>
#include <glm/common.hpp>
#include <limits>
#include <string>

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

TcMotion::TcMotion(Context& context, const Scene& now, const Scene& next, int frame,
                   int hole_passes) {
    if (now.mesh.triangles.size() != next.mesh.triangles.size()) {
        throw Error("temporal caching: the scene has " + std::to_string(now.mesh.triangles.size()) +
                    " triangles at frame " + std::to_string(frame) + " and " +
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
    moved_slot_ = Buffer<int>(context, slots, "tc_moved_slot");
    moved_triangles_ = Buffer<shared::Triangle>(context, moved, "tc_moved_triangles");
    const std::vector<shared::TcEmitter> emitters_now = unshadowed_emitters(now);
    const std::vector<shared::TcEmitter> emitters_next = unshadowed_emitters(next);
    if (emitters_now.size() != emitters_next.size()) {
        throw Error("temporal caching: the emitters differ between frame " + std::to_string(frame) +
                    " and the next");
    }
    emitters_now_ = Buffer<shared::TcEmitter>(context, emitters_now, "tc_emitters_now");
    emitters_next_ = Buffer<shared::TcEmitter>(context, emitters_next, "tc_emitters_next");
    params_.emitter_count = static_cast<int>(emitters_now.size());
    params_.emitters_change =
        emitters_now.empty() ? 0
                             : std::memcmp(emitters_now.data(), emitters_next.data(),
                                           emitters_now.size() * sizeof(shared::TcEmitter)) != 0;
    params_.hole_passes = hole_passes;
}

shared::TcParams TcMotion::params(int cell_layout) const {
    shared::TcParams params = params_;
    params.cell_layout = cell_layout;
    return params;
}

}  // namespace rc
