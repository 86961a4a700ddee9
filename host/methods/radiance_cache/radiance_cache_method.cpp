// `--method rc`: radiance caching (DESIGN.md §6.4) as a registered method. The glossy lobes'
// indirect light comes from radiance records (RadianceCache) where the BRDF tables represent the
// lobe, by Monte Carlo where they do not; the diffuse lobes keep irradiance caching's records,
// with its options, whose first level the radiance records' hemisphere rays read at their hits.
#include <algorithm>
#include <memory>

#include "methods/glossy_method.h"
#include "methods/irradiance_cache/ic_memory.h"
#include "methods/irradiance_cache/ic_options.h"
#include "methods/method.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/temporal/temporal_cache.h"
#include "methods/temporal/temporal_options.h"
#include "methods/temporal/temporal_radiance_cache.h"
#include "shared/radiance_cache.h"
#include "shared/sh_rotation_zxz.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

std::vector<OptionSpec> radiance_cache_option_specs() {
    std::vector<OptionSpec> specs = {
        OptionSpec{
            "--rc-order", "", "N|auto",
            "rc: largest spherical-harmonic order n (n^2 coefficients per channel) of the BRDF "
            "tables and the radiance records, 1-10; lobes that need more go to Monte Carlo "
            "(default auto: 10)"}
            .integers(1, RC_SH_MAX_ORDER, {"auto"}),
        OptionSpec{"--rc-max-error", "", "E",
                   "rc: largest relative L2 error of a BRDF lobe's representation in (0, 1); each "
                   "material gets the lowest order below it (default 0.1)"}
            .numbers(1e-6, 0.999999),
        OptionSpec{"--rc-rays", "", "N", "rc: hemisphere rays per radiance record (default 4096)"}
            .integers(16, 1 << 16),
        {"--rc-cache-out", "", "FILE", "rc: save the radiance records"},
        {"--rc-cache-in", "", "FILE",
         "rc: start from the radiance records of a saved cache (same scene, frame, accuracy and "
         "order)"},
    };
    for (OptionSpec& spec : glossy_method_ic_option_specs()) {
        specs.push_back(std::move(spec));
    }
    for (OptionSpec& spec : temporal_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

int parse_order(const ParsedArguments& arguments) {
    const std::string text = arguments.value("--rc-order", "auto");
    if (text == "auto") {
        return 0;
    }
    return static_cast<int>(arguments.integer("--rc-order", 0));
}

RadianceCacheOptions parse_options(const ParsedArguments& arguments, const MethodSettings& settings,
                                   const IrradianceCacheOptions& ic) {
    RadianceCacheOptions rc;
    rc.order = parse_order(arguments);
    rc.max_error = arguments.number("--rc-max-error", rc.max_error);
    rc.rays = static_cast<int>(arguments.integer("--rc-rays", rc.rays));
    rc.accuracy = ic.accuracy;
    rc.min_spacing = ic.min_spacing;
    rc.max_spacing = ic.max_spacing;
    rc.seed = ic.seed;
    rc.max_depth = ic.max_depth;
    rc.rr_depth = ic.rr_depth;
    rc.cache_in = arguments.value("--rc-cache-in");
    rc.cache_out = arguments.value("--rc-cache-out");
    if (!rc.cache_out.empty()) {
        check_writable_parent(rc.cache_out, "--rc-cache-out");
    }
    if (settings.frame_count > 1 && (!rc.cache_in.empty() || !rc.cache_out.empty())) {
        throw Error("--rc-cache-in/--rc-cache-out take one frame", kExitUsage);
    }
    check_radiance_cache_options(rc);
    return rc;
}

class RadianceCaching final : public Method {
   public:
    RadianceCaching(const ParsedArguments& arguments, const MethodSettings& settings)
        : ic_(parse_irradiance_cache_options(arguments, settings)),
          rc_(parse_options(arguments, settings, ic_)) {
        const TemporalOptions temporal = parse_temporal_options(arguments);
        if (!temporal.enabled) {
            return;
        }
        if (temporal.lifespan == TemporalLifespan::kDeparture) {
            throw Error(
                "--temporal-lifespan departure: --method ic only (rc's radiance records' "
                "lifespans are by change)",
                kExitUsage);
        }
        refuse_cache_files_with_temporal(!ic_.cache_in.empty() || !ic_.cache_out.empty() ||
                                             !rc_.cache_in.empty() || !rc_.cache_out.empty(),
                                         "--cache-in/--cache-out, --rc-cache-in/--rc-cache-out");
        const long long last =
            static_cast<long long>(settings.first_frame) + std::max(settings.frame_count, 1) - 1;
        temporal_glossy_ = std::make_unique<TemporalRadianceCache>(
            rc_, temporal, settings.first_frame, static_cast<int>(last));
        temporal_ = std::make_unique<TemporalIrradianceCache>(ic_, temporal, settings.first_frame,
                                                              settings.frame_count);
        temporal_->set_glossy(temporal_glossy_.get());
    }

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        if (temporal_) {
            refuse_temporal_on_several_devices(frame_devices(frame));
            FrameResult result = temporal_->render_frame(frame, hooks);
            const nlohmann::json& t = result.stats["temporal"];
            const nlohmann::json& r = t["radiance"];
            log_note(t["records"].dump() + " irradiance records, " + r["records"].dump() +
                     " radiance records (" + r["created"].dump() + " new, " +
                     r["recomputed"].dump() + " recomputed, " + r["reused"].dump() + " reused, " +
                     r["dropped"].dump() + " dropped)");
            return result;
        }
        // The materials are the same at every frame: their BRDF tables are built once.
        RadianceCache glossy(frame, rc_, tables_);
        tables_ = glossy.tables();
        IrradianceCacheStats stats;
        FrameResult result = render_with_glossy_cache(frame, ic_, glossy, &stats);
        const RadianceCacheStats& rc = glossy.stats();
        result.rays += rc.record_rays;
        result.stats["radiance_cache"] = radiance_stats(rc);
        log_note(std::to_string(stats.records) + " irradiance records, " +
                 std::to_string(rc.records) + " radiance records (order " +
                 std::to_string(rc.order) + ")");
        return result;
    }

    // The diffuse records' batches and the final pass (irradiance_cache.h); the radiance
    // records and the glossy buffer stay on the first device. Temporal caching renders on one.
    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override {
        std::vector<ProgramRequest> programs = irradiance_cache_programs(ic_, RC_RADIANCE_PATH);
        programs.push_back({"radiance_cache/radiance_cache.cl", ""});
        programs.push_back({"radiance_cache/rc_cache.cl", ""});
        programs.push_back(
            {"radiance_cache/rc_record_cells.cl", radiance_source_define(RC_RADIANCE_RECORDS)});
        programs.push_back({"glossy/glossy_placement.cl", ""});
        if (temporal_) {
            programs.push_back({"temporal/temporal.cl", ""});
            programs.push_back({"temporal/tc_radiance.cl", ""});
        }
        return programs;
    }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        // RadianceCache::glossy_samples: the queries and glossy samples, with the splat's x90
        // table and counter.
        const GlossySampleBytes glossy = {
            sizeof(shared::RcQuery), sizeof(shared::RcGlossySample),
            buffer_bytes(RC_SH_X90_TABLE_SIZE, sizeof(float)) + buffer_bytes(1, sizeof(unsigned))};
        DeviceMemoryNeed need = irradiance_cache_device_need(ic_, scene, glossy);
        need.excludes += ", the radiance records, their batches and the BRDF tables";
        return need;
    }

   private:
    static nlohmann::json radiance_stats(const RadianceCacheStats& rc) {
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
        return {
            {"records", rc.records},
            {"order", rc.order},
            {"strata", {rc.strata_m, rc.strata_n}},
            {"materials", materials},
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

    IrradianceCacheOptions ic_;
    RadianceCacheOptions rc_;
    std::shared_ptr<const BrdfTables> tables_;                // built at the first frame
    std::unique_ptr<TemporalRadianceCache> temporal_glossy_;  // with --temporal
    std::unique_ptr<TemporalIrradianceCache> temporal_;
};

}  // namespace

MethodEntry radiance_cache_method_entry() {
    return {"rc",
            "radiance caching: glossy lobes from spherical-harmonic records with gradients, "
            "rotated and interpolated; diffuse lobes from irradiance records",
            radiance_cache_option_specs(), glossy_method_aovs("rc-order"),
            [](const ParsedArguments& arguments, const MethodSettings& settings) {
                return std::make_unique<RadianceCaching>(arguments, settings);
            }};
}

}  // namespace rc
