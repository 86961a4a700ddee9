// Placement's candidate thinning, shared by the record-based caches (DESIGN.md §6.2 step 2).
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

namespace rc {

// Keeps, in order, the candidates (positions, normals) farther than their minimum influence
// radius from the ones kept before (with similar normals): one batch then places no two records
// where one would do. Returns indices into the candidates.
std::vector<size_t> thin_candidates(const std::vector<glm::vec3>& positions,
                                    const std::vector<glm::vec3>& normals,
                                    const std::vector<float>& min_influence);

}  // namespace rc
