#include "methods/caching/placement_passes.h"

#include "methods/caching/candidate_thinning.h"

namespace rc {

size_t run_placement_passes(bool until_covered, const std::function<UncoveredCandidates()>& find,
                            const std::function<void(const std::vector<size_t>&)>& add) {
    const int passes = until_covered ? kMaxPlacementPasses : 1;
    for (int pass = 0; pass < passes; ++pass) {
        const UncoveredCandidates open = find();
        const std::vector<size_t> chosen =
            thin_candidates(open.positions, open.normals, open.min_influence);
        if (chosen.empty()) {
            return 0;
        }
        if (until_covered && pass + 1 == passes) {
            return chosen.size();  // the bound: these stay uncovered
        }
        add(chosen);
    }
    return 0;
}

}  // namespace rc
