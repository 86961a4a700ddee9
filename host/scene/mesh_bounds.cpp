#include "scene/mesh_bounds.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

namespace rc {

float mesh_diagonal(const TriangleMesh& mesh) {
    if (mesh.positions.empty()) {
        return 0.0f;
    }
    glm::vec3 lower(std::numeric_limits<float>::max());
    glm::vec3 upper(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    return glm::length(upper - lower);
}

}  // namespace rc
