#include "methods/temporal/temporal_options.h"

#include "util/error.h"

namespace rc {

std::vector<OptionSpec> temporal_option_specs() {
    return {
        {"--temporal", "", "",
         "ic, rc: temporal caching over --frames: records (rc: irradiance and radiance records) "
         "live across frames while their light changes less than --temporal-accuracy allows, "
         "replaced in place when they expire (docs/temporal-caching.md)"},
        OptionSpec{"--temporal-gradients", "", "interpolated|extrapolated|none",
                   "--temporal: a record's value over its frames: interpolated towards its "
                   "replacement (two passes, default), extrapolated from its reprojected next "
                   "frame (one pass), or held"}
            .one_of({"interpolated", "extrapolated", "none"}),
        OptionSpec{"--temporal-lifespan", "", "change|departure",
                   "--temporal (ic, interpolated gradients): what bounds a record's lifespan: its "
                   "change since its creation (default) or its departure from the line towards "
                   "its replacement, from a second reprojection two frames ahead"}
            .one_of({"change", "departure"}),
        OptionSpec{"--temporal-accuracy", "", "A",
                   "--temporal: a^t, the largest relative change of a record's irradiance (rc: "
                   "of its radiance's SH coefficients) over its lifespan, estimated by "
                   "reprojection (default 0.02)"}
            .numbers(1e-4, 10.0),
        OptionSpec{"--temporal-max-frames", "", "N",
                   "--temporal: the longest lifespan of a record, in frames (default 20)"}
            .integers(1, 1 << 20),
        OptionSpec{"--temporal-moving-hits", "", "trace|cache",
                   "--temporal: irradiance records' hemisphere hits on objects moving into or out "
                   "of the frame path-trace the light beyond them (trace, default) or get "
                   "deeper-level records, which live one frame (cache)"}
            .one_of({"trace", "cache"}),
    };
}

TemporalOptions parse_temporal_options(const ParsedArguments& arguments) {
    TemporalOptions t;
    t.enabled = arguments.has("--temporal");
    if (!t.enabled) {
        for (const char* option :
             {"--temporal-gradients", "--temporal-lifespan", "--temporal-accuracy",
              "--temporal-max-frames", "--temporal-moving-hits"}) {
            if (arguments.has(option)) {
                throw Error(std::string(option) + " needs --temporal", kExitUsage);
            }
        }
        return t;
    }
    if (arguments.has("--temporal-gradients")) {
        const std::string value = arguments.value("--temporal-gradients");
        if (value == "interpolated") {
            t.gradients = TemporalGradients::kInterpolated;
        } else if (value == "extrapolated") {
            t.gradients = TemporalGradients::kExtrapolated;
        } else if (value == "none") {
            t.gradients = TemporalGradients::kNone;
        } else {
            throw Error("--temporal-gradients: expected interpolated, extrapolated or none, got '" +
                            value + "'",
                        kExitUsage);
        }
    }
    if (arguments.has("--temporal-moving-hits")) {
        const std::string value = arguments.value("--temporal-moving-hits");
        if (value != "trace" && value != "cache") {
            throw Error("--temporal-moving-hits: expected trace or cache, got '" + value + "'",
                        kExitUsage);
        }
        t.cache_moving_hits = value == "cache";
    }
    if (arguments.has("--temporal-lifespan")) {
        const std::string value = arguments.value("--temporal-lifespan");
        if (value != "change" && value != "departure") {
            throw Error("--temporal-lifespan: expected change or departure, got '" + value + "'",
                        kExitUsage);
        }
        t.lifespan =
            value == "departure" ? TemporalLifespan::kDeparture : TemporalLifespan::kChange;
        if (t.lifespan == TemporalLifespan::kDeparture &&
            t.gradients != TemporalGradients::kInterpolated) {
            throw Error(
                "--temporal-lifespan departure: needs --temporal-gradients interpolated, "
                "got " +
                    temporal_gradients_name(t.gradients),
                kExitUsage);
        }
    }
    t.accuracy = static_cast<float>(arguments.number("--temporal-accuracy", t.accuracy));
    t.max_frames = static_cast<int>(arguments.integer("--temporal-max-frames", t.max_frames));
    return t;
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

void refuse_temporal_on_several_devices(size_t devices) {
    if (devices > 1) {
        throw Error("--temporal renders on one device; --device names " + std::to_string(devices),
                    kExitUsage);
    }
}

}  // namespace rc
