#include "methods/caching/pipeline_options.h"

#include "methods/light_samples.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

Spacing spacing_option(const std::string& option, const std::string& text) {
    return parse_spacing(text, option);
}

std::string spacing_text(const Spacing& spacing) {
    return option_value_text(spacing.value) + (spacing.world ? "u" : "px");
}

}  // namespace

OptionTable<PipelineSettings> pipeline_option_table() {
    using O = PipelineSettings;
    OptionTable<O> table;
    table
        .number("--accuracy", "A", &O::accuracy, 1e-3, 1.0,
                "interpolation accuracy a in (0, 1] (Radiance's -aa): a record serves points "
                "within a R")
        .knob(KnobDirection::kDecrease)
        .integer("--ic-rays", "N", &O::rays, 4, 1 << 16,
                 "hemisphere rays per record (Radiance's -ad)")
        .knob(KnobDirection::kIncrease)
        .integer("--ic-deeper-rays", "N", &O::deeper_rays, 4, 1 << 16,
                 "hemisphere rays per record of the deeper cache levels (the course: deeper "
                 "levels use fewer samples)")
        .default_note("a quarter of --ic-rays")
        .knob(KnobDirection::kIncrease)
        .parsed<Spacing>(
            "--ic-min-spacing", "L", &O::min_spacing, "length",
            [](const std::string& text) { return spacing_option("--ic-min-spacing", text); },
            spacing_text,
            "smallest record radius R_min, in projected pixels (\"3\", \"3px\") or scene units "
            "(\"5u\")")
        .knob(KnobDirection::kDecrease)
        .parsed<Spacing>(
            "--ic-max-spacing", "L", &O::max_spacing, "length",
            [](const std::string& text) { return spacing_option("--ic-max-spacing", text); },
            spacing_text, "largest record radius R_max, as --ic-min-spacing takes")
        .knob(KnobDirection::kDecrease)
        .integer("--ic-bounces", "N", &O::bounces, 1, 8,
                 "cache levels (1: path tracing beyond the hemisphere rays' hits; N: records at N "
                 "levels, the last path traced beyond)")
        .default_note("2; 1 with --ic-ivg")
        .knob(KnobDirection::kIncrease)
        .path("--cache-out", &O::cache_out, "save the irradiance cache's records (every level)")
        .path("--cache-in", &O::cache_in,
              "start from the records of a saved cache (same scene, frame and accuracy)");
    add_light_samples_option(table, &O::light_samples);
    return table;
}

PipelineSettings pipeline_defaults() {
    PipelineSettings options;
    options.light_samples = kDefaultLightSamples;
    return options;
}

void finish_pipeline_settings(const PipelineSettings& options) {
    if (!options.cache_out.empty()) {
        check_writable_parent(options.cache_out, "--cache-out");
    }
}

PipelineSettings pipeline_settings(PipelineSettings options, const MethodSettings& settings) {
    if (settings.frame_count > 1 && (!options.cache_in.empty() || !options.cache_out.empty())) {
        throw Error("--cache-in/--cache-out take one frame", kExitUsage);
    }
    settings.apply_to(options);
    options.records_overlay = settings.writes_layer("records");
    return options;
}

}  // namespace rc
