#include "scene/mesh_bounds.h"

#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

#include "util/error.h"

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

void check_least_extent(const TriangleMesh& mesh, float least, const std::string& who,
                        const std::string& where, const std::string& least_name,
                        const std::string& why) {
    const float diagonal = mesh_diagonal(mesh);
    if (!(diagonal > 0.0f && diagonal < least)) {
        return;
    }
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, "%.3g", static_cast<double>(diagonal));
    const std::string measured = numbers;
    std::snprintf(numbers, sizeof numbers, "%.3g", static_cast<double>(least));
    throw Error(who + "the scene's extent (its bounding box's diagonal)" + where + " is " +
                measured + " scene units, below " + least_name + " (" + numbers + "): " + why);
}

}  // namespace rc
