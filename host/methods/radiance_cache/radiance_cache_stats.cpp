// Radiance caching's statistics of a frame (the statistics file's "radiance_cache" object;
// docs/radiance-caching.md): the adaptive order's split per material, the placement passes, the
// records, rays and reflections with their rates, and the seconds of each step.
#include "methods/radiance_cache/radiance_cache.h"

namespace rc {

nlohmann::json RadianceCache::statistics() const {
    const RadianceCacheStats& rc = stats_;
    nlohmann::json materials = nlohmann::json::array();
    for (const BrdfTableSummary& m : rc.materials) {
        materials.push_back({{"name", m.name},
                             {"kind", brdf_kind_name(m.kind)},
                             {"order", m.order},
                             {"fallback_fraction", m.fallback_fraction}});
    }
    nlohmann::json passes = nlohmann::json::array();
    for (const PlacementPass& pass : rc.placement.passes) {
        passes.push_back({{"stride", pass.stride},
                          {"candidates", pass.candidates},
                          {"uncovered", pass.uncovered},
                          {"records", pass.records}});
    }
    const double coefficients = static_cast<double>(rc.records) * 3.0 * rc.order * rc.order;
    return {{"records", rc.records},
            {"order", rc.order},
            {"strata", {rc.strata_m, rc.strata_n}},
            {"materials", materials},
            {"tables_built", rc.tables_built},
            {"placement_passes", passes},
            {"glossy_samples", rc.placement.glossy_samples},
            {"fallback_samples", rc.placement.fallback_samples},
            {"fallback_fraction", rc.placement.glossy_samples > 0
                                      ? static_cast<double>(rc.placement.fallback_samples) /
                                            static_cast<double>(rc.placement.glossy_samples)
                                      : 0.0},
            {"record_rays", rc.record_rays},
            {"reflections", rc.reflections},
            {"coefficients_projected_per_second",
             rc.placement.record_seconds > 0.0 ? coefficients / rc.placement.record_seconds : 0.0},
            {"reflections_per_second",
             rc.splat_seconds > 0.0 ? static_cast<double>(rc.reflections) / rc.splat_seconds : 0.0},
            {"seconds",
             {{"tables", rc.table_seconds},
              {"queries", rc.query_seconds},
              {"placement", rc.placement.placement_seconds},
              {"records", rc.placement.record_seconds},
              {"splatting", rc.splat_seconds}}}};
}

}  // namespace rc
