#include "methods/irradiance_vector_grid/ivg_options.h"

#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {

std::vector<OptionSpec> ivg_option_specs() {
    return {
        {"--grid", "", "NxMxK|auto",
         "ivg, ivg-gather, ic --ic-ivg: voxels of the irradiance vector grid per axis, or auto "
         "(about 32k vertices over the scene's bounding box; default)"},
        OptionSpec{"--photons", "", "N", "grid: photons to trace (default: 8 per grid vertex)"}
            .integers(1, 1LL << 31),
        OptionSpec{"--ivg-interp", "", "NAME",
                   "grid: spatial interpolation, trilinear (default) or tricubic (Catmull-Rom)"}
            .one_of({"trilinear", "tricubic"}),
        {"--ivg-compressed", "", "",
         "grid: read the 16-bit colour + direction layout (RR-6983 §4.2)"},
        {"--ivg-include-direct", "", "",
         "grid: record unbounced photons too; the grid then replaces next-event estimation for "
         "the diffuse lobe where it is read"},
        {"--grid-out", "", "FILE", "grid: save the normalised grid"},
        {"--grid-in", "", "FILE",
         "grid: load a saved grid instead of tracing photons (same scene, frame, depth limit)"},
    };
}

void refuse_ivg_options(const ParsedArguments& arguments, const std::string& why) {
    for (const OptionSpec& spec : ivg_option_specs()) {
        if (arguments.has(spec.name)) {
            throw Error(spec.name + " " + why, kExitUsage);
        }
    }
}

IvgOptions ivg_options(const ParsedArguments& arguments, const MethodSettings& settings) {
    IvgOptions options;
    options.cells = parse_grid_resolution(arguments.value("--grid", "auto"));
    options.photons = static_cast<uint64_t>(arguments.integer("--photons", 0));
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
    if (settings.frame_count > 1 && (!options.grid_in.empty() || !options.grid_out.empty())) {
        throw Error("--grid-in/--grid-out take one frame", kExitUsage);
    }
    options.seed = settings.seed;
    options.max_depth = settings.max_depth;
    options.rr_depth = settings.rr_depth;
    return options;
}

std::unique_ptr<IrradianceVectorGrid> build_frame_grid(const FrameScene& frame,
                                                       const IvgOptions& options,
                                                       const FrameHooks& hooks,
                                                       FrameResult* result) {
    hooks.progress(0.0, "photons");
    auto grid = std::make_unique<IrradianceVectorGrid>(frame);
    IvgStats stats;
    grid->build(options, &stats);
    result->stats["grid"] = ivg_stats_json(stats);
    result->rays += stats.rays;
    log_note("irradiance vector grid " + std::to_string(stats.cells[0]) + "x" +
             std::to_string(stats.cells[1]) + "x" + std::to_string(stats.cells[2]) + ", " +
             std::to_string(stats.photons) + " photons");
    return grid;
}

nlohmann::json ivg_stats_json(const IvgStats& stats) {
    const double seconds = stats.trace_seconds;
    nlohmann::json json = {
        {"cells", stats.cells},
        {"photons", stats.photons},
        {"loaded", stats.loaded},
        {"crossings", stats.crossings},
        {"photon_rays", stats.rays},
        {"photons_per_second", seconds > 0.0 ? static_cast<double>(stats.photons) / seconds : 0.0},
        {"grid_bytes", stats.grid_bytes},
        {"cell_planes",
         {{"plane_cells", stats.plane_cells},
          {"unsupported_cells", stats.unsupported_cells},
          {"empty_cells", stats.empty_cells},
          {"planes", stats.planes}}},
        {"seconds",
         {{"photons", stats.trace_seconds},
          {"normalize", stats.normalize_seconds},
          {"planes", stats.planes_seconds}}}};
    if (!stats.devices.empty()) {
        nlohmann::json devices = nlohmann::json::array();
        for (const IvgDeviceShare& d : stats.devices) {
            devices.push_back({{"device", d.device},
                               {"batches", d.batches},
                               {"photons", d.photons},
                               {"seconds", d.seconds}});
        }
        json["devices"] = devices;
    }
    return json;
}

}  // namespace rc
