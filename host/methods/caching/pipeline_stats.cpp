#include "methods/caching/pipeline_stats.h"

#include "methods/device_shares.h"
namespace rc {

void add_irradiance_cache_stats(const PipelineStats& stats, const PipelineSettings& options,
                                nlohmann::json* out) {
    nlohmann::json passes = nlohmann::json::array();
    for (const PlacementPass& pass : stats.passes) {
        passes.push_back({{"level", pass.level},
                          {"stride", pass.stride},
                          {"candidates", pass.candidates},
                          {"uncovered", pass.uncovered},
                          {"records", pass.records}});
    }
    size_t computed = 0;
    for (size_t level_size : stats.level_records) {
        computed += level_size;
    }
    computed -= stats.loaded_records;
    nlohmann::json& s = *out;
    s["spp"] = options.spp;
    s["light_samples"] = options.light_samples;
    s["records"] = stats.records;
    s["loaded_records"] = stats.loaded_records;
    s["level_records"] = stats.level_records;
    s["placement_passes"] = passes;
    s["strata"] = {stats.strata_m, stats.strata_n};
    if (stats.level_records.size() > 1) {
        s["deeper_strata"] = {stats.deeper_strata_m, stats.deeper_strata_n};
    }
    s["rays_per_record"] = computed > 0 ? static_cast<double>(stats.record_rays) / computed : 0.0;
    s["record_rays"] = stats.record_rays;
    s["shading_rays"] = stats.shading_rays;
    s["cache_bytes"] = stats.cache_bytes;
    s["seconds"] = {{"gbuffer", stats.gbuffer_seconds},     {"placement", stats.placement_seconds},
                    {"records", stats.record_seconds},      {"insertion", stats.insertion_seconds},
                    {"splatting", stats.splatting_seconds}, {"shading", stats.shading_seconds}};
    add_device_shares(stats.devices, &s, [](const PipelineDeviceShare& d) {
        return nlohmann::json{{"device", d.device},
                              {"record_ranges", d.record_ranges},
                              {"records", d.records},
                              {"record_seconds", d.record_seconds},
                              {"chunks", d.chunks},
                              {"pixels", d.pixels},
                              {"final_seconds", d.final_seconds}};
    });
}

}  // namespace rc
