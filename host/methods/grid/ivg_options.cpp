#include "methods/grid/ivg_options.h"

#include "methods/device_shares.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {

namespace {

std::string grid_resolution_text(const std::array<int, 3>& cells) {
    if (cells[0] == 0) {
        return "auto";
    }
    return std::to_string(cells[0]) + "x" + std::to_string(cells[1]) + "x" +
           std::to_string(cells[2]);
}

}  // namespace

OptionTable<IvgOptions> ivg_option_table() {
    using O = IvgOptions;
    OptionTable<O> table;
    table
        .parsed<std::array<int, 3>>(
            "--grid", "NxMxK|auto", &O::cells, "resolution", parse_grid_resolution,
            grid_resolution_text,
            "voxels of the irradiance vector grid per axis, or auto (about 32k vertices over the "
            "scene's bounding box)")
        .knob(KnobDirection::kIncrease)
        .integer("--photons", "N", &O::photons, 1, 1LL << 31, "photons to trace into the grid")
        .default_note("8 per grid vertex")
        .knob(KnobDirection::kIncrease)
        .choice<int>("--ivg-interp", &O::interpolation,
                     {{"trilinear", RC_IVG_TRILINEAR}, {"tricubic", RC_IVG_TRICUBIC}},
                     "the grid's spatial interpolation: trilinear or tricubic (Catmull-Rom)")
        .flag("--ivg-compressed", &O::compressed,
              "read the grid's 16-bit colour + direction layout (RR-6983 §4.2)")
        .flag("--ivg-include-direct", &O::include_direct,
              "record unbounced photons too; the grid then replaces next-event estimation for "
              "the diffuse lobe where it is read")
        .path("--grid-out", &O::grid_out, "save the normalised grid")
        .path("--grid-in", &O::grid_in,
              "load a saved grid instead of tracing photons (same scene, frame, depth limit)");
    return table;
}

void refuse_ivg_options(const ParsedArguments& arguments, const std::string& why) {
    for (const OptionInfo& info : ivg_option_table().infos()) {
        if (arguments.has(info.spec.name)) {
            throw Error(info.spec.name + " " + why, kExitUsage);
        }
    }
}

void finish_ivg_options(const IvgOptions& options, const ParsedArguments& arguments) {
    if (!options.grid_out.empty()) {
        check_writable_parent(options.grid_out, "--grid-out");
    }
    if (!options.grid_in.empty() && arguments.has("--photons")) {
        throw Error("--photons and --grid-in exclude each other (a loaded grid traces none)",
                    kExitUsage);
    }
}

IvgOptions ivg_options(IvgOptions options, const MethodSettings& settings) {
    if (settings.frame_count > 1 && (!options.grid_in.empty() || !options.grid_out.empty())) {
        throw Error("--grid-in/--grid-out take one frame", kExitUsage);
    }
    settings.apply_to(options);
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
    add_device_shares(stats.devices, &json, [](const IvgDeviceShare& d) {
        return nlohmann::json{{"device", d.device},
                              {"batches", d.batches},
                              {"photons", d.photons},
                              {"seconds", d.seconds}};
    });
    return json;
}

}  // namespace rc
