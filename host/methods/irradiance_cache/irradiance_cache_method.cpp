// `--method ic`: irradiance caching (DESIGN.md §6.2) as a registered method: its options, its
// statistics per frame, (with --ic-ivg) the irradiance vector grid as the radiance its
// hemisphere rays read beyond their hits, and (with --glossy) the glossy caches serving the
// specular lobes of the materials it names (methods/caching/glossy_plan.h).
#include <memory>

#include "methods/caching/cache_pipeline.h"
#include "methods/caching/glossy_caches.h"
#include "methods/caching/glossy_method.h"
#include "methods/caching/glossy_plan.h"
#include "methods/caching/pipeline_memory.h"
#include "methods/caching/pipeline_options.h"
#include "methods/caching/pipeline_stats.h"
#include "methods/caching/record_passes.h"
#include "methods/grid/ivg_options.h"
#include "methods/light_samples.h"
#include "methods/method.h"
#include "methods/temporal/temporal_cache.h"
#include "methods/temporal/temporal_options.h"
#include "util/error.h"
#include "util/log.h"
#include "util/timing.h"

namespace rc {
namespace {

// ic's options: the irradiance records', the grid's (with --ic-ivg) and temporal caching's.
struct IrradianceCachingOptions {
    PipelineSettings records = pipeline_defaults();
    bool with_grid = false;  // --ic-ivg
    IvgOptions grid;
    TemporalOptions temporal;
    GlossySpec glossy;  // --glossy: what serves each material's specular lobe
};

OptionTable<IrradianceCachingOptions> irradiance_caching_table() {
    using O = IrradianceCachingOptions;
    OptionTable<O> table;
    table.include(pipeline_option_table(), &O::records)
        .flag("--ic-ivg", &O::with_grid,
              "hemisphere rays read the irradiance vector grid at their hits instead of path "
              "tracing beyond them (the grid's options apply)")
        .include(ivg_option_table(), &O::grid)
        .include(temporal_option_table(), &O::temporal)
        .parsed<GlossySpec>(
            "--glossy", "SPEC", &O::glossy, "text", parse_glossy_spec, glossy_spec_text,
            "what serves the specular lobes: path (path tracing), a glossy cache (" +
                glossy_cache_names() +
                ") for every material, or a list NAME=CACHE,... of the scene's "
                "materials with *=CACHE for the rest (the others: path); the "
                "caches take the options --method rc and sdrc take when none is given");
    return table;
}

// The rules between ic's options: the grid's need --ic-ivg (which makes one cache level the
// default), the temporal ones --temporal, which excludes the grid and cache files.
void finish_irradiance_caching(IrradianceCachingOptions& options,
                               const ParsedArguments& arguments) {
    finish_pipeline_settings(options.records);
    check_temporal_options(options.temporal, arguments);
    if (options.with_grid) {
        finish_ivg_options(options.grid, arguments);
        if (!arguments.has("--ic-bounces")) {
            options.records.bounces = 1;
        }
    } else {
        refuse_ivg_options(arguments, "applies to --method ivg, ivg-gather, or ic with --ic-ivg");
    }
    if (!options.glossy.caches().empty() && (options.with_grid || options.temporal.enabled)) {
        throw Error("--glossy " + glossy_spec_text(options.glossy) +
                        ": the glossy caches read the records' first level, not the grid "
                        "(--ic-ivg), and do not cache over time (--temporal)",
                    kExitUsage);
    }
    if (options.temporal.enabled) {
        if (options.with_grid) {
            throw Error("--temporal: the hemisphere rays cannot read the grid (--ic-ivg)",
                        kExitUsage);
        }
        refuse_cache_files_with_temporal(
            !options.records.cache_in.empty() || !options.records.cache_out.empty(),
            "--cache-in/--cache-out");
    }
}

class IrradianceCaching final : public Method {
   public:
    IrradianceCaching(const IrradianceCachingOptions& options, const MethodSettings& settings)
        : options_(pipeline_settings(options.records, settings)),
          with_grid_(options.with_grid),
          glossy_(options.glossy),
          time_(settings.time) {
        if (options.temporal.enabled) {
            temporal_ = std::make_unique<TemporalIrradianceCache>(
                options_, options.temporal, settings.first_frame, settings.frame_count);
        }
        if (with_grid_) {
            grid_options_ = ivg_options(options.grid, settings);
        }
    }

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        if (temporal_) {
            refuse_temporal_on_several_devices(frame_devices(frame));
            FrameResult result = temporal_->render_frame(frame, hooks);
            const nlohmann::json& t = result.stats["temporal"];
            log_note(t["records"].dump() + " irradiance records (" + t["created"].dump() +
                     " new, " + t["recomputed"].dump() + " recomputed, " + t["reused"].dump() +
                     " reused, " + t["dropped"].dump() + " dropped)");
            return result;
        }
        if (!glossy_.caches().empty()) {
            return render_glossy_frame(frame, hooks);
        }
        // The grid (--ic-ivg) is built first; a budget (--time) counts its build.
        const auto start = SteadyClock::now();
        FrameResult grid_result;
        std::unique_ptr<IrradianceVectorGrid> grid;
        if (with_grid_) {
            grid = build_frame_grid(frame, grid_options_, hooks, &grid_result);
        }
        const double time = time_ > 0.0 ? std::max(time_ - seconds_since(start), 1e-9) : 0.0;
        CachePipeline cache(frame, {.beyond = grid.get()});
        PipelineStats stats;
        FrameResult result = render_record_passes(cache, options_, time, hooks, nullptr, &stats);
        result.rays += grid_result.rays;
        result.stats.update(grid_result.stats);
        log_note(std::to_string(stats.records) + " irradiance records");
        return result;
    }

    // The record batches and the final pass; placement and insertion stay on the first device
    // and the host, and --ic-ivg's hemisphere rays on the first device (where its grid is).
    // Temporal caching renders on one device.
    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override {
        std::vector<ProgramRequest> programs =
            cache_pipeline_programs(options_, with_grid_ ? RC_RADIANCE_GRID : RC_RADIANCE_PATH);
        if (with_grid_) {
            programs.push_back({"irradiance_vector_grid/irradiance_vector_grid.cl", ""});
        }
        if (temporal_) {
            programs.push_back({"temporal/temporal.cl", ""});
        }
        for (const ProgramRequest& request : glossy_programs(glossy_)) {
            programs.push_back(request);
        }
        return programs;
    }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        check_glossy_spec(glossy_, scene);
        std::string excludes;
        const GlossySampleBytes glossy = glossy_sample_bytes(glossy_, &excludes);
        DeviceMemoryNeed cache = cache_pipeline_device_need(options_, scene, glossy);
        cache.excludes += excludes;
        if (temporal_) {
            cache.excludes += ", their reprojection and the look-ahead frames' scenes and BVHs";
        }
        // The grid is built first and read until the frame ends.
        return with_grid_ ? with_grid_need(grid_options_, scene, cache) : cache;
    }

   private:
    // A frame with the glossy caches of --glossy serving the specular lobes of their materials
    // (methods/caching/glossy_method.h, as --method rc and sdrc render theirs).
    FrameResult render_glossy_frame(const FrameScene& frame, const FrameHooks& hooks) {
        const std::unique_ptr<GlossyMix> glossy = make_glossy_mix(frame, options_, glossy_);
        PipelineStats stats;
        FrameResult result = render_with_glossy_cache(
            frame, options_, *glossy, time_, hooks,
            [&](FrameResult& pass, const PipelineStats&) {
                pass.stats.update(glossy->statistics());
            },
            &stats);
        log_note(std::to_string(stats.records) +
                 " irradiance records; glossy lobes: " + glossy_spec_text(glossy_));
        return result;
    }

    PipelineSettings options_;
    bool with_grid_;
    GlossySpec glossy_;
    double time_;  // --time (0: --spp)
    std::unique_ptr<TemporalIrradianceCache> temporal_;
    IvgOptions grid_options_;
};

}  // namespace

MethodEntry irradiance_cache_method_entry() {
    return method_entry<IrradianceCachingOptions>(
        {.name = "ic",
         .summary = "irradiance caching: records with gradients, neighbor clamping, interpolated",
         .aovs = {std::begin(kCachePipelineAovs), std::end(kCachePipelineAovs)},
         .table = irradiance_caching_table(),
         .finish = finish_irradiance_caching,
         .check =
             [](const IrradianceCachingOptions& options, const MethodSettings& settings) {
                 pipeline_settings(options.records, settings);
                 refuse_time_with_temporal(options.temporal, settings.time);
                 if (options.with_grid) {
                     ivg_options(options.grid, settings);
                 }
             },
         .create =
             [](const IrradianceCachingOptions& options, const MethodSettings& settings) {
                 return std::make_unique<IrradianceCaching>(options, settings);
             }});
}

}  // namespace rc
