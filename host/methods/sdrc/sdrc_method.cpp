// `--method sdrc`: spatial directional radiance caching (DESIGN.md §6.5) as a registered method.
// The glossy lobes' indirect light comes from SDRC's records and their L-trees (SdrcCache); the
// diffuse lobes keep irradiance caching's records, with its options, whose first level SDRC's
// rays read at their hits. With --temporal, SDRC's records and the irradiance records live
// across frames (TemporalSdrcCache driven by TemporalIrradianceCache, as `rc --temporal`).
#include <memory>

#include "methods/caching/glossy_method.h"
#include "methods/caching/pipeline_memory.h"
#include "methods/caching/pipeline_options.h"
#include "methods/method.h"
#include "methods/sdrc/sdrc_cache.h"
#include "methods/sdrc/temporal_sdrc_cache.h"
#include "methods/temporal/temporal_glossy_method.h"
#include "methods/temporal/temporal_options.h"
#include "shared/radiance_cache.h"
#include "util/error.h"
#include "util/log.h"

namespace rc {
namespace {

// sdrc's options: its own, the irradiance records' for the diffuse lobes and temporal caching's.
struct SdrcMethodOptions {
    SdrcOptions sdrc;
    PipelineSettings records = pipeline_defaults();
    TemporalOptions temporal;
};

OptionTable<SdrcMethodOptions> sdrc_option_table() {
    using O = SdrcOptions;
    OptionTable<O> own;
    own.integer("--sdrc-samples", "N|auto", &O::samples, 16, 65536,
                "directions a new record samples from its lobe and keeps in its L-tree (auto: 3 "
                "x interp x spp within [64, 8192])",
                {"auto"}, 0)
        .knob(KnobDirection::kIncrease)
        .integer("--sdrc-interp", "M", &O::interp, 1, 64,
                 "lobe directions per camera sample looked up in the L-trees")
        .knob(KnobDirection::kIncrease)
        .number("--sdrc-max-radius", "R", &O::max_radius, 1e-4, 2.0,
                "ceiling of a lookup's radius in the paraboloid map")
        .knob(KnobDirection::kDecrease)
        .number("--sdrc-memory", "MIB", &O::memory_mib, 1e-3, 1e9,
                "cap on the L-trees' memory; a render that needs more stops with an error")
        .unit("MiB");
    OptionTable<SdrcMethodOptions> table;
    table.include(own, &SdrcMethodOptions::sdrc)
        .include(pipeline_option_table(), &SdrcMethodOptions::records)
        .include(temporal_option_table(), &SdrcMethodOptions::temporal);
    return table;
}

// The rules between sdrc's options: with --temporal, no cache files and lifespans by change.
void finish_sdrc(SdrcMethodOptions& options, const ParsedArguments& arguments) {
    finish_pipeline_settings(options.records);
    const PipelineSettings& ic = options.records;
    check_glossy_temporal_options(options.temporal, arguments,
                                  !ic.cache_in.empty() || !ic.cache_out.empty(),
                                  "--cache-in/--cache-out");
}

// SDRC's options with the irradiance records' they share (a, the spacing) and the shared
// settings.
SdrcOptions sdrc_options(SdrcOptions sdrc, const PipelineSettings& ic) {
    share_record_settings(ic, &sdrc);
    return sdrc;
}

class SpatialDirectionalRadianceCaching final : public Method {
   public:
    SpatialDirectionalRadianceCaching(const SdrcMethodOptions& options,
                                      const MethodSettings& settings)
        : ic_(pipeline_settings(options.records, settings)),
          sdrc_(sdrc_options(options.sdrc, ic_)),
          time_(settings.time),
          temporal_(
              temporal_glossy_render<TemporalSdrcCache>(sdrc_, ic_, options.temporal, settings)) {}

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        if (temporal_) {
            return temporal_->render_frame(frame, hooks, "SDRC");
        }
        SdrcCache glossy(frame, sdrc_);
        PipelineStats stats;
        FrameResult result = render_with_glossy_cache(
            frame, ic_, glossy, time_, hooks,
            [&](FrameResult& pass, const PipelineStats&) {
                pass.stats["sdrc"] = glossy.statistics();
            },
            &stats);
        const SdrcStats& s = glossy.stats();
        log_note(std::to_string(stats.records) + " irradiance records, " +
                 std::to_string(s.records) + " SDRC records (" + std::to_string(s.ltree_nodes) +
                 " L-tree samples), " +
                 std::to_string(static_cast<int>(
                     100.0 *
                     (s.directions > 0 ? static_cast<double>(s.answered) / s.directions : 0.0))) +
                 "% of directions from the cache");
        return result;
    }

    // The diffuse records' batches and the final pass (cache_pipeline.h); the SDRC records,
    // L-trees and the glossy buffer stay on the first device.
    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override {
        std::vector<ProgramRequest> programs = cache_pipeline_programs(ic_, RC_RADIANCE_PATH);
        programs.push_back({"sdrc/sdrc.cl", ""});
        programs.push_back({"sdrc/sdrc_trace.cl", radiance_source_define(RC_RADIANCE_RECORDS)});
        programs.push_back({"caching/glossy_placement.cl", ""});
        if (temporal_) {
            programs.push_back({"temporal/temporal.cl", ""});
        }
        return programs;
    }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        // SdrcCache::glossy_samples: the queries and glossy samples.
        const GlossySampleBytes glossy = {sizeof(shared::RcQuery), sizeof(shared::RcGlossySample),
                                          0};
        DeviceMemoryNeed need = cache_pipeline_device_need(ic_, scene, glossy);
        need.excludes += ", the SDRC records, their batches and their L-trees";
        return need;
    }

   private:
    PipelineSettings ic_;
    SdrcOptions sdrc_;
    double time_;                                     // --time (0: --spp)
    std::unique_ptr<TemporalGlossyRender> temporal_;  // with --temporal
};

}  // namespace

MethodEntry sdrc_method_entry() {
    return method_entry<SdrcMethodOptions>(
        {.name = "sdrc",
         .summary = "spatial directional radiance caching: glossy lobes from records of "
                    "importance-sampled radiance samples in per-record kd-trees (L-trees), "
                    "range-queried; diffuse lobes from irradiance records",
         .aovs = glossy_method_aovs("sdrc-hits"),
         .table = sdrc_option_table(),
         .finish = finish_sdrc,
         .check =
             [](const SdrcMethodOptions& options, const MethodSettings& settings) {
                 pipeline_settings(options.records, settings);
                 refuse_time_with_temporal(options.temporal, settings.time);
             },
         .create =
             [](const SdrcMethodOptions& options, const MethodSettings& settings) {
                 return std::make_unique<SpatialDirectionalRadianceCaching>(options, settings);
             }});
}

}  // namespace rc
