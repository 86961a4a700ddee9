// SDRC's statistics of a frame (the statistics file's "sdrc" object; docs/sdrc.md): the records,
// the placement passes, the L-trees' size, the interpolation's directions, hits and misses with
// their rates, and the seconds of each step.
#include "methods/sdrc/sdrc_cache.h"

namespace rc {

nlohmann::json SdrcCache::statistics() const {
    const SdrcStats& s = stats_;
    nlohmann::json passes = nlohmann::json::array();
    for (const PlacementPass& pass : s.placement.passes) {
        passes.push_back({{"stride", pass.stride},
                          {"candidates", pass.candidates},
                          {"uncovered", pass.uncovered},
                          {"records", pass.records}});
    }
    const auto ratio = [](double a, double b) { return b > 0.0 ? a / b : 0.0; };
    return {{"records", s.records},
            {"samples_per_record", s.samples},
            {"placement_passes", passes},
            {"glossy_samples", s.placement.glossy_samples},
            {"ltree_nodes", s.ltree_nodes},
            {"ltree_bytes", s.ltree_nodes * sizeof(shared::LTreeNode)},
            {"record_rays", s.record_rays},
            {"directions", s.directions},
            {"answered", s.answered},
            {"hit_rate", ratio(static_cast<double>(s.answered), static_cast<double>(s.directions))},
            {"range_queries", s.range_queries},
            {"misses", s.misses},
            {"unstored_misses", s.unstored},
            {"miss_rays", s.miss_rays},
            {"rebuilds", s.rebuilds},
            {"directions_per_second",
             ratio(static_cast<double>(s.directions), s.interpolation_seconds)},
            {"range_queries_per_second",
             ratio(static_cast<double>(s.range_queries), s.interpolation_seconds)},
            {"seconds",
             {{"queries", s.query_seconds},
              {"placement", s.placement.placement_seconds},
              {"records", s.placement.record_seconds},
              {"tree_builds", s.tree_build_seconds},
              {"interpolation", s.interpolation_seconds}}}};
}

}  // namespace rc
