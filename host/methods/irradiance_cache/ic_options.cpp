#include "methods/irradiance_cache/ic_options.h"

#include "methods/irradiance_vector_grid/ivg_options.h"
#include "methods/light_samples.h"
#include "methods/temporal/temporal_options.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {

std::vector<OptionSpec> irradiance_cache_option_specs() {
    std::vector<OptionSpec> specs = {
        OptionSpec{"--accuracy", "", "A",
                   "ic: interpolation accuracy a in (0, 1] (Radiance's -aa): a record serves "
                   "points within a R (default 0.35)"}
            .numbers(1e-3, 1.0),
        OptionSpec{"--ic-rays", "", "N",
                   "ic: hemisphere rays per record (Radiance's -ad; default 1024)"}
            .integers(4, 1 << 16),
        OptionSpec{
            "--ic-deeper-rays", "", "N",
            "ic: hemisphere rays per record of the deeper cache levels (the course: deeper levels "
            "use fewer samples; default a quarter of --ic-rays)"}
            .integers(4, 1 << 16),
        {"--ic-min-spacing", "", "L",
         "ic: smallest record radius R_min, in projected pixels (\"3\", \"3px\") or scene units "
         "(\"5u\") (default 8px)"},
        {"--ic-max-spacing", "", "L", "ic: largest record radius R_max (default 64px)"},
        OptionSpec{
            "--ic-bounces", "", "N",
            "ic: cache levels (1: path tracing beyond the hemisphere rays' hits; N: records at N "
            "levels, the last path traced beyond; default 2, 1 with --ic-ivg)"}
            .integers(1, 8),
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
    for (OptionSpec& spec : temporal_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

IrradianceCacheOptions parse_irradiance_cache_options(const ParsedArguments& arguments,
                                                      const MethodSettings& settings) {
    IrradianceCacheOptions ic;
    ic.accuracy = static_cast<float>(arguments.number("--accuracy", ic.accuracy));
    ic.rays = static_cast<int>(arguments.integer("--ic-rays", ic.rays));
    ic.deeper_rays = static_cast<int>(arguments.integer("--ic-deeper-rays", 0));
    if (arguments.has("--ic-min-spacing")) {
        ic.min_spacing = parse_spacing(arguments.value("--ic-min-spacing"), "--ic-min-spacing");
    }
    if (arguments.has("--ic-max-spacing")) {
        ic.max_spacing = parse_spacing(arguments.value("--ic-max-spacing"), "--ic-max-spacing");
    }
    // Two cache levels unless the grid serves the hemisphere rays' hits (one level only).
    const int bounces = arguments.has("--ic-ivg") ? 1 : ic.bounces;
    ic.bounces = static_cast<int>(arguments.integer("--ic-bounces", bounces));
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

}  // namespace rc
