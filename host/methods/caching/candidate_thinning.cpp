#include "methods/caching/candidate_thinning.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_map>

namespace rc {

std::vector<size_t> thin_candidates(const std::vector<glm::vec3>& positions,
                                    const std::vector<glm::vec3>& normals,
                                    const std::vector<float>& min_influence) {
    float cell = 0.0f;
    for (float r : min_influence) {
        cell = std::max(cell, r);
    }
    std::vector<size_t> kept;
    if (!(cell > 0.0f)) {
        for (size_t c = 0; c < positions.size(); ++c) {
            kept.push_back(c);
        }
        return kept;
    }
    std::unordered_map<long long, std::vector<size_t>> kept_in_cell;
    auto key = [](long long x, long long y, long long z) {
        return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL);
    };
    for (size_t c = 0; c < positions.size(); ++c) {
        const glm::vec3 p = positions[c];
        const glm::vec3 n = normals[c];
        const long long cx = static_cast<long long>(std::floor(p.x / cell));
        const long long cy = static_cast<long long>(std::floor(p.y / cell));
        const long long cz = static_cast<long long>(std::floor(p.z / cell));
        bool near = false;
        for (long long dz = -1; dz <= 1 && !near; ++dz) {
            for (long long dy = -1; dy <= 1 && !near; ++dy) {
                for (long long dx = -1; dx <= 1 && !near; ++dx) {
                    const auto found = kept_in_cell.find(key(cx + dx, cy + dy, cz + dz));
                    if (found == kept_in_cell.end()) {
                        continue;
                    }
                    for (size_t other : found->second) {
                        const float d = glm::length(p - positions[other]);
                        if (d < std::max(min_influence[c], min_influence[other]) &&
                            glm::dot(n, normals[other]) > 0.9f) {
                            near = true;
                            break;
                        }
                    }
                }
            }
        }
        if (!near) {
            kept_in_cell[key(cx, cy, cz)].push_back(c);
            kept.push_back(c);
        }
    }
    return kept;
}

}  // namespace rc
