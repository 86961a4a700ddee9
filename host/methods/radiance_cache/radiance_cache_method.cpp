// `--method rc`: radiance caching (DESIGN.md §6.4) as a registered method. The glossy lobes'
// indirect light comes from radiance records (RadianceCache) where the BRDF tables represent the
// lobe, by Monte Carlo where they do not; the diffuse lobes keep irradiance caching's records,
// with its options, whose first level the radiance records' hemisphere rays read at their hits.
#include <memory>

#include "methods/caching/glossy_method.h"
#include "methods/caching/pipeline_memory.h"
#include "methods/caching/pipeline_options.h"
#include "methods/method.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/radiance_cache/temporal_radiance_cache.h"
#include "methods/temporal/temporal_glossy_method.h"
#include "methods/temporal/temporal_options.h"
#include "shared/radiance_cache.h"
#include "shared/sh_rotation_zxz.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

// rc's options: its own, the irradiance records' for the diffuse lobes and temporal caching's.
struct RadianceCachingOptions {
    RadianceCacheOptions radiance;
    PipelineSettings records = pipeline_defaults();
    TemporalOptions temporal;
};

OptionTable<RadianceCachingOptions> radiance_caching_table() {
    using O = RadianceCacheOptions;
    OptionTable<O> own;
    own.integer("--rc-order", "N|auto", &O::order, 1, RC_SH_MAX_ORDER,
                "largest spherical-harmonic order n (n^2 coefficients per channel) of the BRDF "
                "tables and the radiance records; lobes that need more go to Monte Carlo (auto: " +
                    std::to_string(RC_SH_MAX_ORDER) + ")",
                {"auto"}, 0)
        .knob(KnobDirection::kIncrease)
        .number("--rc-max-error", "E", &O::max_error, 1e-6, 0.999999,
                "largest relative L2 error of a BRDF lobe's representation in (0, 1); each "
                "material gets the lowest order below it")
        .knob(KnobDirection::kDecrease)
        .integer("--rc-rays", "N", &O::rays, 16, 1 << 16, "hemisphere rays per radiance record")
        .knob(KnobDirection::kIncrease)
        .path("--rc-cache-out", &O::cache_out, "save the radiance records")
        .path("--rc-cache-in", &O::cache_in,
              "start from the radiance records of a saved cache (same scene, frame, accuracy and "
              "order)");
    OptionTable<RadianceCachingOptions> table;
    table.include(own, &RadianceCachingOptions::radiance)
        .include(pipeline_option_table(), &RadianceCachingOptions::records)
        .include(temporal_option_table(), &RadianceCachingOptions::temporal);
    return table;
}

// The rules between rc's options: --rc-cache-out's folder writable; with --temporal, no cache
// files and lifespans by change.
void finish_radiance_caching(RadianceCachingOptions& options, const ParsedArguments& arguments) {
    finish_pipeline_settings(options.records);
    if (!options.radiance.cache_out.empty()) {
        check_writable_parent(options.radiance.cache_out, "--rc-cache-out");
    }
    check_radiance_cache_options(options.radiance);
    const PipelineSettings& ic = options.records;
    const RadianceCacheOptions& rc = options.radiance;
    check_glossy_temporal_options(options.temporal, arguments,
                                  !ic.cache_in.empty() || !ic.cache_out.empty() ||
                                      !rc.cache_in.empty() || !rc.cache_out.empty(),
                                  "--cache-in/--cache-out, --rc-cache-in/--rc-cache-out");
}

// The radiance records' options with the irradiance records' they share (a, the spacing) and
// the shared settings; Error (exit status 2) for cache files with several frames.
RadianceCacheOptions radiance_record_options(RadianceCacheOptions rc, const PipelineSettings& ic,
                                             const MethodSettings& settings) {
    share_record_settings(ic, &rc);
    if (settings.frame_count > 1 && (!rc.cache_in.empty() || !rc.cache_out.empty())) {
        throw Error("--rc-cache-in/--rc-cache-out take one frame", kExitUsage);
    }
    return rc;
}

class RadianceCaching final : public Method {
   public:
    RadianceCaching(const RadianceCachingOptions& options, const MethodSettings& settings)
        : ic_(pipeline_settings(options.records, settings)),
          rc_(radiance_record_options(options.radiance, ic_, settings)),
          time_(settings.time),
          temporal_(temporal_glossy_render<TemporalRadianceCache>(rc_, ic_, options.temporal,
                                                                  settings)) {}

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        if (temporal_) {
            return temporal_->render_frame(frame, hooks, "radiance");
        }
        // The materials are the same at every frame: their BRDF tables are built once.
        RadianceCache glossy(frame, rc_, tables_);
        tables_ = glossy.tables();
        PipelineStats stats;
        FrameResult result = render_with_glossy_cache(
            frame, ic_, glossy, time_, hooks,
            [&](FrameResult& pass, const PipelineStats&) {
                pass.stats["radiance_cache"] = glossy.statistics();
            },
            &stats);
        const RadianceCacheStats& rc = glossy.stats();
        log_note(std::to_string(stats.records) + " irradiance records, " +
                 std::to_string(rc.records) + " radiance records (order " +
                 std::to_string(rc.order) + ")");
        return result;
    }

    // The diffuse records' batches and the final pass (cache_pipeline.h); the radiance
    // records and the glossy buffer stay on the first device. Temporal caching renders on one.
    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override {
        std::vector<ProgramRequest> programs = cache_pipeline_programs(ic_, RC_RADIANCE_PATH);
        programs.push_back({"radiance_cache/radiance_cache.cl", ""});
        programs.push_back({"radiance_cache/rc_cache.cl", ""});
        programs.push_back(
            {"radiance_cache/rc_record_cells.cl", radiance_source_define(RC_RADIANCE_RECORDS)});
        programs.push_back({"caching/glossy_placement.cl", ""});
        if (temporal_) {
            programs.push_back({"temporal/temporal.cl", ""});
        }
        return programs;
    }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        // RadianceCache::glossy_samples: the queries and glossy samples, with the splat's x90
        // table and counter.
        const GlossySampleBytes glossy = {
            sizeof(shared::RcQuery), sizeof(shared::RcGlossySample),
            buffer_bytes(RC_SH_X90_TABLE_SIZE, sizeof(float)) + buffer_bytes(1, sizeof(unsigned))};
        DeviceMemoryNeed need = cache_pipeline_device_need(ic_, scene, glossy);
        need.excludes += ", the radiance records, their batches and the BRDF tables";
        return need;
    }

   private:
    PipelineSettings ic_;
    RadianceCacheOptions rc_;
    double time_;                                     // --time (0: --spp)
    std::shared_ptr<const BrdfTables> tables_;        // built at the first frame
    std::unique_ptr<TemporalGlossyRender> temporal_;  // with --temporal
};

}  // namespace

MethodEntry radiance_cache_method_entry() {
    return method_entry<RadianceCachingOptions>(
        {.name = "rc",
         .summary = "radiance caching: glossy lobes from spherical-harmonic records with "
                    "gradients, rotated and interpolated; diffuse lobes from irradiance records",
         .aovs = glossy_method_aovs("rc-order"),
         .table = radiance_caching_table(),
         .finish = finish_radiance_caching,
         .check =
             [](const RadianceCachingOptions& options, const MethodSettings& settings) {
                 radiance_record_options(options.radiance,
                                         pipeline_settings(options.records, settings), settings);
                 refuse_time_with_temporal(options.temporal, settings.time);
             },
         .create =
             [](const RadianceCachingOptions& options, const MethodSettings& settings) {
                 return std::make_unique<RadianceCaching>(options, settings);
             }});
}

}  // namespace rc
