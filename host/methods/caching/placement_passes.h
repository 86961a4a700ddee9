// The placement loop every record-based cache shares (DESIGN.md §6.2 step 2; irradiance records
// in CachePipeline::cover, glossy records in GlossyPlacement::cover): each pass finds the
// candidates no record covers yet, thins them so that one pass places no two records where one
// would do (thin_candidates), and adds records at the ones kept, until none is left uncovered.
// A record covers its own position, so the passes end; they are bounded all the same, so that a
// scene beyond float precision (a pixel narrower than a record can be) cannot hang placement.
#pragma once

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <vector>

namespace rc {

// The most passes one placement runs.
constexpr int kMaxPlacementPasses = 64;

// The candidates a pass found uncovered: where they are, their normals and their minimum
// influence radius (accuracy times the minimum spacing).
struct UncoveredCandidates {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<float> min_influence;
};

// Runs placement passes: `find` gives the candidates uncovered now, `add` places records at the
// chosen ones (indices into what `find` gave last). One pass, or with `until_covered` passes until
// a pass finds nothing to place (at most kMaxPlacementPasses). Returns how many candidates the
// last pass chose that were left uncovered: 0 unless the bound cut placement short.
size_t run_placement_passes(bool until_covered, const std::function<UncoveredCandidates()>& find,
                            const std::function<void(const std::vector<size_t>&)>& add);

}  // namespace rc
