#include "methods/temporal/temporal_options.h"

#include "util/error.h"

namespace rc {

OptionTable<TemporalOptions> temporal_option_table() {
    using O = TemporalOptions;
    OptionTable<O> table;
    table
        .flag("--temporal", &O::enabled,
              "temporal caching over --frames: records (rc: irradiance and radiance records) "
              "live across frames while their light changes less than --temporal-accuracy "
              "allows, replaced in place when they expire (docs/temporal-caching.md)")
        .choice<TemporalGradients>("--temporal-gradients", &O::gradients,
                                   {{"interpolated", TemporalGradients::kInterpolated},
                                    {"extrapolated", TemporalGradients::kExtrapolated},
                                    {"none", TemporalGradients::kNone}},
                                   "--temporal: a record's value over its frames: interpolated "
                                   "towards its replacement (two passes), extrapolated from its "
                                   "reprojected next frame (one pass), or held")
        .choice<TemporalLifespan>(
            "--temporal-lifespan", &O::lifespan,
            {{"change", TemporalLifespan::kChange}, {"departure", TemporalLifespan::kDeparture}},
            "--temporal (ic, interpolated gradients): what bounds a record's "
            "lifespan: its change since its creation or its departure from "
            "the line towards its replacement, from a second reprojection "
            "two frames ahead")
        .number("--temporal-accuracy", "A", &O::accuracy, 1e-4, 10.0,
                "--temporal: a^t, the largest relative change of a record's irradiance (rc: of "
                "its radiance's SH coefficients) over its lifespan, estimated by reprojection")
        .knob(KnobDirection::kDecrease)
        .integer("--temporal-max-frames", "N", &O::max_frames, 1, 1 << 20,
                 "--temporal: the longest lifespan of a record that sees change, in frames; "
                 "given, of every record (not given, records made while only the camera moves "
                 "serve until something else moves)")
        .unit("frames")
        .choice<bool>("--temporal-moving-hits", &O::cache_moving_hits,
                      {{"trace", false}, {"cache", true}},
                      "--temporal: irradiance records' hemisphere hits on objects moving into or "
                      "out of the frame path-trace the light beyond them (trace) or get "
                      "deeper-level records, which live one frame (cache)");
    return table;
}

void check_temporal_options(TemporalOptions& t, const ParsedArguments& arguments) {
    t.max_frames_given = arguments.has("--temporal-max-frames");
    if (!t.enabled) {
        for (const OptionInfo& info : temporal_option_table().infos()) {
            if (info.spec.name != "--temporal" && arguments.has(info.spec.name)) {
                throw Error(info.spec.name + " needs --temporal", kExitUsage);
            }
        }
        return;
    }
    if (t.lifespan == TemporalLifespan::kDeparture &&
        t.gradients != TemporalGradients::kInterpolated) {
        throw Error("--temporal-lifespan departure: needs --temporal-gradients interpolated, got " +
                        temporal_gradients_name(t.gradients),
                    kExitUsage);
    }
}

std::string temporal_gradients_name(TemporalGradients gradients) {
    switch (gradients) {
        case TemporalGradients::kNone:
            return "none";
        case TemporalGradients::kExtrapolated:
            return "extrapolated";
        case TemporalGradients::kInterpolated:
            return "interpolated";
    }
    return "?";
}

std::string temporal_lifespan_name(TemporalLifespan lifespan) {
    return lifespan == TemporalLifespan::kDeparture ? "departure" : "change";
}

void refuse_cache_files_with_temporal(bool given, const std::string& options) {
    if (given) {
        throw Error(
            "--temporal: the records live across frames, not in cache files (" + options + ")",
            kExitUsage);
    }
}

void refuse_time_with_temporal(const TemporalOptions& options, double time) {
    if (options.enabled && time > 0.0) {
        throw Error(
            "--time: temporal caching renders --spp camera samples a frame, not by time "
            "(--temporal)",
            kExitUsage);
    }
}

void refuse_temporal_on_several_devices(size_t devices) {
    if (devices > 1) {
        throw Error("--temporal renders on one device; --device names " + std::to_string(devices),
                    kExitUsage);
    }
}

}  // namespace rc
