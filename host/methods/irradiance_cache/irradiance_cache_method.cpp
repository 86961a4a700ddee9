// `--method ic`: irradiance caching (DESIGN.md §6.2) as a registered method: its options, its
// statistics per frame, and (with --ic-ivg) the irradiance vector grid as the radiance its
// hemisphere rays read beyond their hits.
#include <memory>

#include "methods/irradiance_cache/irradiance_cache.h"
#include "methods/irradiance_vector_grid/ivg_options.h"
#include "methods/light_samples.h"
#include "methods/method.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

std::vector<OptionSpec> irradiance_cache_option_specs() {
    std::vector<OptionSpec> specs = {
        {"--accuracy", "", "A",
         "ic: interpolation accuracy a in (0, 1] (Radiance's -aa): a record serves points within "
         "a R (default 0.35)"},
        {"--ic-rays", "", "N", "ic: hemisphere rays per record (Radiance's -ad; default 1024)"},
        {"--ic-min-spacing", "", "L",
         "ic: smallest record radius R_min, in projected pixels (\"3\", \"3px\") or scene units "
         "(\"5u\") (default 8px)"},
        {"--ic-max-spacing", "", "L", "ic: largest record radius R_max (default 64px)"},
        {"--ic-bounces", "", "N",
         "ic: cache levels (1: path tracing beyond the hemisphere rays' hits; N: records at N "
         "levels, the last path traced beyond; default 2, 1 with --ic-ivg)"},
        {"--cache-out", "", "FILE", "ic: save the irradiance cache's records (every level)"},
        {"--cache-in", "", "FILE",
         "ic: start from the records of a saved cache (same scene, frame and accuracy)"},
        {"--ic-ivg", "", "",
         "ic: hemisphere rays read the irradiance vector grid at their hits instead of path "
         "tracing beyond them (the grid's options apply)"},
        kLightSamplesOption,
    };
    for (OptionSpec& spec : ivg_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

IrradianceCacheOptions parse_options(const ParsedArguments& arguments,
                                     const MethodSettings& settings) {
    IrradianceCacheOptions ic;
    ic.accuracy = static_cast<float>(arguments.number("--accuracy", ic.accuracy, 1e-3, 1.0));
    ic.rays = static_cast<int>(arguments.integer("--ic-rays", ic.rays, 4, 1 << 16));
    if (arguments.has("--ic-min-spacing")) {
        ic.min_spacing = parse_spacing(arguments.value("--ic-min-spacing"), "--ic-min-spacing");
    }
    if (arguments.has("--ic-max-spacing")) {
        ic.max_spacing = parse_spacing(arguments.value("--ic-max-spacing"), "--ic-max-spacing");
    }
    // Two cache levels unless the grid serves the hemisphere rays' hits (one level only).
    const int bounces = arguments.has("--ic-ivg") ? 1 : ic.bounces;
    ic.bounces = static_cast<int>(arguments.integer("--ic-bounces", bounces, 1, 8));
    ic.light_samples = light_samples(arguments);
    ic.cache_in = arguments.value("--cache-in");
    ic.cache_out = arguments.value("--cache-out");
    if (!ic.cache_out.empty()) {
        check_writable_parent(ic.cache_out, "--cache-out");
    }
    if (settings.frame_count > 1 && (!ic.cache_in.empty() || !ic.cache_out.empty())) {
        throw Error("--cache-in/--cache-out take one frame", kExitUsage);
    }
    settings.apply_to(ic);
    ic.records_overlay = settings.writes_layer("records");
    return ic;
}

class IrradianceCaching final : public Method {
   public:
    IrradianceCaching(const ParsedArguments& arguments, const MethodSettings& settings)
        : options_(parse_options(arguments, settings)), with_grid_(arguments.has("--ic-ivg")) {
        if (with_grid_) {
            grid_options_ = ivg_options(arguments, settings);
        } else {
            refuse_ivg_options(arguments,
                               "applies to --method ivg, ivg-gather, or ic with --ic-ivg");
        }
    }

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        FrameResult result;
        std::unique_ptr<IrradianceVectorGrid> grid;
        if (with_grid_) {
            grid = build_frame_grid(frame, grid_options_, hooks, &result);
        }
        IrradianceCache cache(frame);
        IrradianceCacheOptions options = options_;
        options.source = grid.get();
        IrradianceCacheStats stats;
        result.image = cache.render(options, &stats);
        result.spp = options.spp;
        result.rays += stats.record_rays + stats.shading_rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        add_stats(stats, &result.stats);
        log_note(std::to_string(stats.records) + " irradiance records");
        return result;
    }

   private:
    void add_stats(const IrradianceCacheStats& stats, nlohmann::json* out) const {
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
        s["spp"] = options_.spp;
        s["light_samples"] = options_.light_samples;
        s["records"] = stats.records;
        s["loaded_records"] = stats.loaded_records;
        s["level_records"] = stats.level_records;
        s["placement_passes"] = passes;
        s["strata"] = {stats.strata_m, stats.strata_n};
        s["rays_per_record"] =
            computed > 0 ? static_cast<double>(stats.record_rays) / computed : 0.0;
        s["record_rays"] = stats.record_rays;
        s["shading_rays"] = stats.shading_rays;
        s["cache_bytes"] = stats.cache_bytes;
        s["seconds"] = {
            {"gbuffer", stats.gbuffer_seconds},     {"placement", stats.placement_seconds},
            {"records", stats.record_seconds},      {"insertion", stats.insertion_seconds},
            {"splatting", stats.splatting_seconds}, {"shading", stats.shading_seconds}};
    }

    IrradianceCacheOptions options_;
    bool with_grid_;
    IvgOptions grid_options_;
};

}  // namespace

MethodEntry irradiance_cache_method_entry() {
    return {"ic",
            "irradiance caching: records with gradients, neighbor clamping, interpolated",
            irradiance_cache_option_specs(),
            {std::begin(kIrradianceCacheAovs), std::end(kIrradianceCacheAovs)},
            [](const ParsedArguments& arguments, const MethodSettings& settings) {
                return std::make_unique<IrradianceCaching>(arguments, settings);
            }};
}

}  // namespace rc
