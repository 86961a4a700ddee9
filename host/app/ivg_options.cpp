#include "app/ivg_options.h"

#include "util/error.h"
#include "util/file_io.h"

namespace rc {

std::vector<OptionSpec> ivg_option_specs() {
    return {
        {"--grid", "", "NxMxK|auto",
         "ivg, ivg-gather, ic --ic-ivg: voxels of the irradiance vector grid per axis, or auto "
         "(about 32k vertices over the scene's bounding box; default)"},
        {"--photons", "", "N", "grid: photons to trace (default: 8 per grid vertex)"},
        {"--ivg-interp", "", "NAME",
         "grid: spatial interpolation, trilinear (default) or tricubic (Catmull-Rom)"},
        {"--ivg-compressed", "", "",
         "grid: read the 16-bit colour + direction layout (RR-6983 §4.2)"},
        {"--ivg-include-direct", "", "",
         "grid: record unbounced photons too; the grid then replaces next-event estimation for "
         "the diffuse lobe where it is read"},
        {"--grid-out", "", "FILE", "grid: save the normalised grid"},
        {"--grid-in", "", "FILE",
         "grid: load a saved grid instead of tracing photons (same scene, frame, depth limit)"},
        {"--gather-rays", "", "N", "ivg-gather: gather rays per camera sample (default 16)"},
        {"--ic-ivg", "", "",
         "ic: hemisphere rays read the grid at their hits instead of path tracing beyond them"},
    };
}

bool uses_grid(const std::string& method, const ParsedArguments& arguments) {
    return method == "ivg" || method == "ivg-gather" ||
           (method == "ic" && arguments.has("--ic-ivg"));
}

IvgOptions ivg_options(const ParsedArguments& arguments, const std::string& method) {
    if (arguments.has("--ic-ivg") && method != "ic") {
        throw Error("--ic-ivg applies to --method ic only", kExitUsage);
    }
    if (!uses_grid(method, arguments)) {
        for (const char* option : {"--grid", "--photons", "--ivg-interp", "--ivg-compressed",
                                   "--ivg-include-direct", "--grid-out", "--grid-in"}) {
            if (arguments.has(option)) {
                throw Error(std::string(option) +
                                " applies to --method ivg, ivg-gather, or ic with --ic-ivg",
                            kExitUsage);
            }
        }
    }
    IvgOptions options;
    options.cells = parse_grid_resolution(arguments.value("--grid", "auto"));
    options.photons = static_cast<uint64_t>(arguments.integer("--photons", 0, 1, 1LL << 31));
    const std::string interpolation = arguments.value("--ivg-interp", "trilinear");
    if (interpolation == "trilinear") {
        options.interpolation = RC_IVG_TRILINEAR;
    } else if (interpolation == "tricubic") {
        options.interpolation = RC_IVG_TRICUBIC;
    } else {
        throw Error("--ivg-interp: expected trilinear or tricubic, got '" + interpolation + "'",
                    kExitUsage);
    }
    options.compressed = arguments.has("--ivg-compressed");
    options.include_direct = arguments.has("--ivg-include-direct");
    options.grid_in = arguments.value("--grid-in");
    options.grid_out = arguments.value("--grid-out");
    if (!options.grid_out.empty()) {
        check_writable_parent(options.grid_out, "--grid-out");
    }
    if (!options.grid_in.empty() && arguments.has("--photons")) {
        throw Error("--photons and --grid-in exclude each other (a loaded grid traces none)",
                    kExitUsage);
    }
    return options;
}

int gather_rays(const ParsedArguments& arguments, const std::string& method) {
    if (arguments.has("--gather-rays") && method != "ivg-gather") {
        throw Error("--gather-rays applies to --method ivg-gather only", kExitUsage);
    }
    if (method != "ivg-gather") {
        return 0;
    }
    return static_cast<int>(arguments.integer("--gather-rays", kDefaultGatherRays, 1, 1 << 16));
}

nlohmann::json ivg_stats_json(const IvgStats& stats) {
    const double seconds = stats.trace_seconds;
    return {
        {"cells", stats.cells},
        {"photons", stats.photons},
        {"loaded", stats.loaded},
        {"crossings", stats.crossings},
        {"photon_rays", stats.rays},
        {"photons_per_second", seconds > 0.0 ? static_cast<double>(stats.photons) / seconds : 0.0},
        {"grid_bytes", stats.grid_bytes},
        {"seconds", {{"photons", stats.trace_seconds}, {"normalize", stats.normalize_seconds}}}};
}

}  // namespace rc
