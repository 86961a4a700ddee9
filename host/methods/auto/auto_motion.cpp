#include "methods/auto/auto_motion.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "scene/mesh_bounds.h"

namespace rc {
namespace {

// The farthest any vertex or light moves between the two poses.
double largest_move(const Scene& a, const Scene& b) {
    double move = 0.0;
    const size_t vertices = std::min(a.mesh.positions.size(), b.mesh.positions.size());
    for (size_t i = 0; i < vertices; ++i) {
        move = std::max<double>(move, glm::distance(a.mesh.positions[i], b.mesh.positions[i]));
    }
    const size_t lights = std::min(a.lights.lights.size(), b.lights.lights.size());
    for (size_t i = 0; i < lights; ++i) {
        const auto& p = a.lights.lights[i].position;
        const auto& q = b.lights.lights[i].position;
        move = std::max<double>(move,
                                glm::distance(glm::vec3(p.x, p.y, p.z), glm::vec3(q.x, q.y, q.z)));
    }
    return move;
}

}  // namespace

double clip_motion(const Scene& scene, int first, int last) {
    if (last <= first || scene.animation.empty()) {
        return 0.0;
    }
    Scene now = scene;
    now.set_frame(first);
    const double diagonal = std::max<double>(mesh_diagonal(now.mesh), 1e-30);
    const int pairs = std::min(last - first, 16);
    double motion = 0.0;
    for (int k = 0; k < pairs; ++k) {
        const int frame = first + static_cast<int>((static_cast<long long>(last - first - 1) * k) /
                                                   std::max(pairs - 1, 1));
        Scene a = scene;
        a.set_frame(frame);
        Scene b = scene;
        b.set_frame(frame + 1);
        motion = std::max(motion, largest_move(a, b) / diagonal);
    }
    return motion;
}

}  // namespace rc
