#include "methods/temporal/tc_emitters.h"

#include "util/glm_helpers.h"

namespace rc {

std::vector<shared::TcEmitter> unshadowed_emitters(const Scene& scene) {
    std::vector<shared::TcEmitter> emitters;
    for (const shared::Light& light : scene.lights.lights) {
        if (light.kind != RC_LIGHT_AREA) {
            shared::TcEmitter e{};
            e.light = light;
            emitters.push_back(e);
            continue;
        }
        for (int t = 0; t < light.triangle_count; ++t) {
            const unsigned primitive =
                scene.lights.triangles[static_cast<size_t>(light.first_triangle + t)];
            const glm::uvec3 v = scene.mesh.triangles[primitive];
            shared::TcEmitter e{};
            e.light = light;
            e.v0 = float4_of(scene.mesh.positions[v.x]);
            e.v1 = float4_of(scene.mesh.positions[v.y]);
            e.v2 = float4_of(scene.mesh.positions[v.z]);
            emitters.push_back(e);
        }
    }
    return emitters;
}

}  // namespace rc
