// `radcache render SCENE [options]`.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "app/cli.h"
#include "app/commands.h"
#include "app/device_options.h"
#include "app/ivg_options.h"
#include "app/progress_bar.h"
#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "image/image_io.h"
#include "methods/irradiance_cache/irradiance_cache.h"
#include "methods/irradiance_vector_grid/ivg_method.h"
#include "methods/normals/normals.h"
#include "methods/path_tracer/path_tracer.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// One warning for the NaN or infinite samples a frame dropped, naming the first pixel.
void warn_nonfinite(uint64_t samples, int64_t first_pixel, int width) {
    if (samples > 0) {
        log_warning(std::to_string(samples) +
                    " samples were NaN or infinite and were dropped (first at pixel " +
                    std::to_string(first_pixel % width) + ", " +
                    std::to_string(first_pixel / width) + ")");
    }
}

constexpr const char* kMethods = "pt, ic, ivg, ivg-gather, normals";

std::vector<OptionSpec> render_option_specs() {
    std::vector<OptionSpec> specs = {
        {"--output", "-o", "FILE",
         "output image: .exr (all AOVs), .hdr, .pfm or .png (default out.png); with --frames, "
         "#### in the name becomes the frame number"},
        {"--method", "", "NAME", std::string("rendering method: ") + kMethods + " (default pt)"},
        {"--spp", "", "N", "samples per pixel (default: the scene's render.spp, else 16)"},
        {"--time", "", "SECONDS", "render passes until this much time has passed, not to --spp"},
        {"--seed", "", "N", "random seed (default: the scene's render.seed, else 0)"},
        {"--width", "", "N", "image width in pixels (default: the scene camera's)"},
        {"--height", "", "N", "image height in pixels (default: the scene camera's)"},
        {"--frames", "", "A:B", "render frames A to B of an animated scene, one image each"},
        {"-D", "", "KEY=VALUE",
         "override a render default: method, spp, time, max_depth, rr_depth, seed, exposure", true},
        {"--save-every-pow2", "", "",
         "also write the image after 1, 2, 4, 8, ... samples per pixel (name.sppN.ext)"},
        {"--exposure", "", "STOPS", "exposure applied before 8-bit encoding (default 0)"},
        {"--half", "", "", ".exr: store half floats"},
        {"--aovs", "", "LIST",
         ".exr: the layers to write, comma-separated (default all; pt: beauty, direct, "
         "indirect, albedo, normal, stddev; ic: beauty, direct, indirect, albedo, normal, "
         "coverage, records; ivg, ivg-gather: beauty, direct, indirect, albedo, normal, grid)"},
        {"--stats", "", "FILE", "write timings and counts as JSON"},
        {"--accuracy", "", "A",
         "ic: interpolation accuracy a in (0, 1] (Radiance's -aa): a record serves points within "
         "a R (default 0.35)"},
        {"--ic-rays", "", "N", "ic: hemisphere rays per record (Radiance's -ad; default 1024)"},
        {"--ic-min-spacing", "", "L",
         "ic: smallest record influence radius a R, in pixels (\"8\", \"8px\") or scene units "
         "(\"5u\") (default 8px)"},
        {"--ic-max-spacing", "", "L", "ic: largest record influence radius a R (default 64px)"},
        {"--ic-bounces", "", "N",
         "ic: cache levels (1: path tracing beyond the hemisphere rays' hits; N: records at N "
         "levels, the last path traced beyond; default 1)"},
        {"--cache-out", "", "FILE", "ic: save the irradiance cache's records (every level)"},
        {"--cache-in", "", "FILE",
         "ic: start from the records of a saved cache (same scene, frame and accuracy)"},
        {"--quiet", "-q", "", "print nothing but errors"},
    };
    for (OptionSpec& spec : ivg_option_specs()) {
        specs.push_back(std::move(spec));
    }
    for (OptionSpec& spec : device_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

struct FrameRange {
    int first = 0;
    int last = 0;
    bool given = false;
};

FrameRange parse_frames(const std::string& text) {
    static const std::regex form(R"(^(-?\d+):(-?\d+)$)");
    std::smatch match;
    if (!std::regex_match(text, match, form)) {
        throw Error("--frames: expected A:B, got '" + text + "'", kExitUsage);
    }
    FrameRange range;
    range.first = std::stoi(match[1].str());
    range.last = std::stoi(match[2].str());
    range.given = true;
    if (range.last < range.first) {
        throw Error("--frames: " + text + " ends before it starts", kExitUsage);
    }
    return range;
}

// The output name of a frame: the run of '#' replaced by the zero-padded frame number.
std::filesystem::path frame_path(const std::string& pattern, int frame) {
    const size_t first = pattern.find('#');
    if (first == std::string::npos) {
        return pattern;
    }
    const size_t last = pattern.find_first_not_of('#', first);
    const size_t width = (last == std::string::npos ? pattern.size() : last) - first;
    char number[32];
    std::snprintf(number, sizeof number, "%0*d", static_cast<int>(width), frame);
    return pattern.substr(0, first) + number + pattern.substr(first + width);
}

// name.ext -> name.sppN.ext
std::filesystem::path intermediate_path(const std::filesystem::path& output, int spp) {
    std::filesystem::path path = output;
    path.replace_filename(output.stem().string() + ".spp" + std::to_string(spp) +
                          output.extension().string());
    return path;
}

nlohmann::json kernel_times_json(const Context& context) {
    nlohmann::json kernels = nlohmann::json::object();
    for (const auto& [name, time] : context.kernel_times()) {
        kernels[name] = {
            {"seconds", time.seconds}, {"launches", time.launches}, {"items", time.items}};
    }
    return kernels;
}

}  // namespace

int run_render_command(const std::vector<std::string>& args) {
    const std::vector<OptionSpec> specs = render_option_specs();
    const ParsedArguments arguments = parse_arguments("radcache render", args, specs);
    if (arguments.has("--help")) {
        std::cout << format_help("radcache render SCENE [options]",
                                 "Renders SCENE (a scene.json file) to an image.", specs);
        return 0;
    }
    if (arguments.positionals().size() != 1) {
        throw Error("radcache render needs exactly one scene file (see radcache render --help)",
                    kExitUsage);
    }
    set_quiet(arguments.has("--quiet"));
    const auto total_start = Clock::now();

    // Everything that can be checked before any work.
    const std::string output_pattern = arguments.value("--output", "out.png");
    const FrameRange frames =
        arguments.has("--frames") ? parse_frames(arguments.value("--frames")) : FrameRange{};
    if (frames.given && frames.first != frames.last &&
        output_pattern.find('#') == std::string::npos) {
        throw Error(
            "--output " + output_pattern + ": several frames need a #### pattern in the name",
            kExitUsage);
    }
    check_output_path(frame_path(output_pattern, frames.first));
    const std::filesystem::path stats_path = arguments.value("--stats");
    if (!stats_path.empty()) {
        check_writable_parent(stats_path, "--stats");
    }
    RenderSettings overrides_only;
    for (const std::string& assignment : arguments.values("-D")) {
        overrides_only.apply_override(assignment);  // validates the keys before loading
    }

    ImageWriteOptions write_options;
    write_options.half = arguments.has("--half");
    std::vector<std::string> layers;
    if (arguments.has("--aovs")) {
        std::stringstream list(arguments.value("--aovs"));
        for (std::string layer; std::getline(list, layer, ',');) {
            if (!layer.empty()) {
                layers.push_back(layer);
            }
        }
        if (layers.empty()) {
            throw Error("--aovs: expected a comma-separated list of layers", kExitUsage);
        }
    }
    auto phase_start = Clock::now();
    Scene scene = load_scene(arguments.positionals()[0]);
    const double load_seconds = seconds_since(phase_start);
    if (scene.dropped_degenerate > 0) {
        log_note("dropped " + std::to_string(scene.dropped_degenerate) + " degenerate triangles");
    }
    RenderSettings settings = scene.render;
    for (const std::string& assignment : arguments.values("-D")) {
        settings.apply_override(assignment);
    }
    if (arguments.has("--method")) {
        settings.method = arguments.value("--method");
    }
    const bool grid_method = settings.method == "ivg" || settings.method == "ivg-gather";
    if (settings.method != "pt" && settings.method != "ic" && settings.method != "normals" &&
        !grid_method) {
        throw Error(
            "--method: unknown method '" + settings.method + "' (implemented: " + kMethods + ")",
            kExitUsage);
    }
    for (const std::string& layer : layers) {
        bool known = layer == "beauty";
        if (settings.method == "pt") {
            for (const char* aov : kPathTracerAovs) {
                known = known || layer == aov;
            }
        } else if (settings.method == "ic") {
            for (const char* aov : kIrradianceCacheAovs) {
                known = known || layer == aov;
            }
        } else if (grid_method) {
            for (const char* aov : kIvgAovs) {
                known = known || layer == aov;
            }
        }
        if (!known) {
            throw Error("--aovs: method " + settings.method + " has no layer '" + layer + "'",
                        kExitUsage);
        }
    }
    settings.spp = static_cast<int>(arguments.integer("--spp", settings.spp, 1, 1 << 24));
    settings.time = arguments.number("--time", settings.time, 0.0, 1e7);
    settings.seed = static_cast<uint64_t>(
        arguments.integer("--seed", static_cast<long long>(settings.seed), 0, 1LL << 62));
    settings.exposure =
        static_cast<float>(arguments.number("--exposure", settings.exposure, -64.0, 64.0));
    write_options.exposure = settings.exposure;
    IrradianceCacheOptions ic;
    ic.accuracy = static_cast<float>(arguments.number("--accuracy", ic.accuracy, 1e-3, 1.0));
    ic.rays = static_cast<int>(arguments.integer("--ic-rays", ic.rays, 4, 1 << 16));
    if (arguments.has("--ic-min-spacing")) {
        ic.min_spacing = parse_spacing(arguments.value("--ic-min-spacing"), "--ic-min-spacing");
    }
    if (arguments.has("--ic-max-spacing")) {
        ic.max_spacing = parse_spacing(arguments.value("--ic-max-spacing"), "--ic-max-spacing");
    }
    ic.bounces = static_cast<int>(arguments.integer("--ic-bounces", ic.bounces, 1, 8));
    ic.cache_in = arguments.value("--cache-in");
    ic.cache_out = arguments.value("--cache-out");
    if (!ic.cache_out.empty()) {
        check_writable_parent(ic.cache_out, "--cache-out");
    }
    for (const char* option : {"--accuracy", "--ic-rays", "--ic-min-spacing", "--ic-max-spacing",
                               "--ic-bounces", "--cache-out", "--cache-in"}) {
        if (arguments.has(option) && settings.method != "ic") {
            throw Error(std::string(option) + " applies to --method ic only", kExitUsage);
        }
    }
    for (const char* option : {"--time", "--save-every-pow2"}) {
        if (arguments.has(option) && settings.method != "pt") {
            throw Error(std::string(option) + " applies to --method pt only", kExitUsage);
        }
    }
    if (frames.given && frames.first != frames.last &&
        (!ic.cache_in.empty() || !ic.cache_out.empty())) {
        throw Error("--cache-in/--cache-out take one frame", kExitUsage);
    }
    IvgOptions grid_options = ivg_options(arguments, settings.method);
    grid_options.seed = settings.seed;
    grid_options.max_depth = settings.max_depth;
    grid_options.rr_depth = settings.rr_depth;
    const bool build_grid = uses_grid(settings.method, arguments);
    const int gathers = gather_rays(arguments, settings.method);
    if (frames.given && frames.first != frames.last &&
        (!grid_options.grid_in.empty() || !grid_options.grid_out.empty())) {
        throw Error("--grid-in/--grid-out take one frame", kExitUsage);
    }
    const int width = static_cast<int>(arguments.integer("--width", 0, 1, 1 << 16));
    const int height = static_cast<int>(arguments.integer("--height", 0, 1, 1 << 16));
    auto written = [&](const Image& image) {
        return layers.empty() ? image : select_layers(image, layers);
    };

    phase_start = Clock::now();
    Context context(context_options(arguments));
    const double device_seconds = seconds_since(phase_start);
    log_note("device " + context.device().name + "; " +
             std::to_string(scene.mesh.triangle_count()) + " triangles, " +
             std::to_string(scene.lights.lights.size()) + " lights");

    const int first_frame =
        frames.given ? frames.first : static_cast<int>(scene.animation.frame_start);
    const int last_frame = frames.given ? frames.last : first_frame;
    nlohmann::json frame_stats = nlohmann::json::array();
    double bvh_seconds = 0.0;
    double upload_seconds = 0.0;
    double render_seconds = 0.0;
    double write_seconds = 0.0;
    uint64_t rays = 0;
    uint64_t nonfinite = 0;
    int64_t first_nonfinite_pixel = -1;
    int spp_done = 0;
    int image_width = 0;
    int image_height = 0;
    // Adds a frame's rays and dropped samples to the totals, and warns about the latter.
    auto count_frame = [&](uint64_t frame_rays, uint64_t frame_nonfinite, int64_t first_pixel,
                           int frame_width) {
        rays += frame_rays;
        nonfinite += frame_nonfinite;
        if (first_nonfinite_pixel < 0) {
            first_nonfinite_pixel = first_pixel;
        }
        warn_nonfinite(frame_nonfinite, first_pixel, frame_width);
    };
    Bvh bvh;
    for (int frame = first_frame; frame <= last_frame; ++frame) {
        if (static_cast<double>(frame) != scene.frame) {
            scene.set_frame(frame);
        }
        const std::filesystem::path output = frame_path(output_pattern, frame);
        phase_start = Clock::now();
        bvh = build_bvh(scene.mesh);
        bvh_seconds += seconds_since(phase_start);
        phase_start = Clock::now();
        const DeviceBvh device_bvh(context, bvh);
        const DeviceScene device_scene(context, scene);
        upload_seconds += seconds_since(phase_start);

        phase_start = Clock::now();
        Image image;
        nlohmann::json this_frame = {{"frame", frame}, {"output", output.string()}};
        ProgressBar progress(frames.given ? "frame " + std::to_string(frame) : "render", !quiet());
        std::unique_ptr<IrradianceVectorGrid> grid;
        if (build_grid) {
            progress.update(0.0, "photons");
            grid = std::make_unique<IrradianceVectorGrid>(context, scene, device_bvh, device_scene);
            IvgStats grid_stats;
            grid->build(grid_options, &grid_stats);
            this_frame["grid"] = ivg_stats_json(grid_stats);
            rays += grid_stats.rays;
            log_note("irradiance vector grid " + std::to_string(grid_stats.cells[0]) + "x" +
                     std::to_string(grid_stats.cells[1]) + "x" +
                     std::to_string(grid_stats.cells[2]) + ", " +
                     std::to_string(grid_stats.photons) + " photons");
        }
        if (grid_method) {
            IvgMethod method(context, scene, device_bvh, device_scene, *grid);
            IvgRenderOptions options;
            options.width = width;
            options.height = height;
            options.spp = settings.spp;
            options.seed = settings.seed;
            options.gather_rays = gathers;
            IvgRenderStats stats;
            image = method.render(options, &stats);
            spp_done = settings.spp;
            count_frame(stats.rays, stats.nonfinite_samples, stats.first_nonfinite_pixel,
                        image.width);
            this_frame["spp"] = settings.spp;
            this_frame["gather_rays"] = gathers;
            this_frame["shading_rays"] = stats.rays;
            this_frame["seconds"] = {{"shading", stats.seconds}};
        } else if (settings.method == "ic") {
            IrradianceCache cache(context, scene, device_bvh, device_scene);
            ic.source = grid.get();
            ic.width = width;
            ic.height = height;
            ic.spp = settings.spp;
            ic.seed = settings.seed;
            ic.max_depth = settings.max_depth;
            ic.rr_depth = settings.rr_depth;
            ic.records_overlay = layers.empty() ||
                                 std::find(layers.begin(), layers.end(), "records") != layers.end();
            IrradianceCacheStats stats;
            image = cache.render(ic, &stats);
            spp_done = settings.spp;
            count_frame(stats.record_rays + stats.shading_rays, stats.nonfinite_samples,
                        stats.first_nonfinite_pixel, image.width);
            nlohmann::json passes = nlohmann::json::array();
            for (const PlacementPass& pass : stats.passes) {
                passes.push_back({{"level", pass.level},
                                  {"stride", pass.stride},
                                  {"candidates", pass.candidates},
                                  {"uncovered", pass.uncovered},
                                  {"records", pass.records}});
            }
            this_frame["spp"] = settings.spp;
            this_frame["records"] = stats.records;
            this_frame["loaded_records"] = stats.loaded_records;
            this_frame["level_records"] = stats.level_records;
            this_frame["placement_passes"] = passes;
            this_frame["strata"] = {stats.strata_m, stats.strata_n};
            size_t computed = 0;
            for (size_t level_size : stats.level_records) {
                computed += level_size;
            }
            computed -= stats.loaded_records;
            this_frame["rays_per_record"] =
                computed > 0 ? static_cast<double>(stats.record_rays) / computed : 0.0;
            this_frame["record_rays"] = stats.record_rays;
            this_frame["shading_rays"] = stats.shading_rays;
            this_frame["cache_bytes"] = stats.cache_bytes;
            this_frame["seconds"] = {{"gbuffer", stats.gbuffer_seconds},
                                     {"placement", stats.placement_seconds},
                                     {"records", stats.record_seconds},
                                     {"insertion", stats.insertion_seconds},
                                     {"splatting", stats.splatting_seconds}};
            log_note(std::to_string(stats.records) + " irradiance records");
        } else if (settings.method == "normals") {
            NormalsMethod method(context, scene, device_bvh);
            NormalsOptions options;
            options.width = width;
            options.height = height;
            options.samples_per_pixel = static_cast<unsigned>(settings.spp);
            options.seed = settings.seed;
            image = method.render(options);
            spp_done = settings.spp;
        } else {
            PathTracer tracer(context, scene, device_bvh, device_scene);
            PathTracerOptions options;
            options.width = width;
            options.height = height;
            options.spp = settings.spp;
            options.time_limit = settings.time;
            options.seed = settings.seed;
            options.max_depth = settings.max_depth;
            options.rr_depth = settings.rr_depth;
            if (arguments.has("--save-every-pow2")) {
                options.on_power_of_two = [&](int spp, const Image& partial) {
                    write_image(intermediate_path(output, spp), written(partial), write_options);
                };
            }
            options.on_progress = [&](double fraction, int spp) {
                progress.update(fraction, std::to_string(spp) + " spp");
            };
            PathTracerStats stats;
            image = tracer.render(options, &stats);
            spp_done = stats.spp;
            count_frame(stats.rays, stats.nonfinite_samples, stats.first_nonfinite_pixel,
                        image.width);
            this_frame["spp"] = stats.spp;
            this_frame["rays"] = stats.rays;
            this_frame["seconds"] = stats.seconds;
        }
        progress.finish();
        render_seconds += seconds_since(phase_start);
        image_width = image.width;
        image_height = image.height;

        phase_start = Clock::now();
        write_image(output, written(image), write_options);
        write_seconds += seconds_since(phase_start);
        log_note("wrote " + output.string() + " (" + std::to_string(image.width) + "x" +
                 std::to_string(image.height) + ", " + std::to_string(spp_done) + " spp)");
        frame_stats.push_back(this_frame);
    }

    if (!stats_path.empty()) {
        const double total = seconds_since(total_start);
        double kernel_seconds = 0.0;
        for (const auto& [name, time] : context.kernel_times()) {
            kernel_seconds += time.seconds;
        }
        nlohmann::json stats;
        stats["method"] = settings.method;
        stats["device"] = context.device().name;
        stats["scene"] = scene.path.string();
        stats["triangles"] = scene.mesh.triangle_count();
        stats["lights"] = scene.lights.lights.size();
        stats["dropped_degenerate_triangles"] = scene.dropped_degenerate;
        stats["resolution"] = {image_width, image_height};
        stats["spp"] = spp_done;
        stats["seed"] = settings.seed;
        stats["max_depth"] = settings.max_depth;
        stats["frames"] = frame_stats;
        stats["seconds"] = {{"total", total},           {"load", load_seconds},
                            {"device", device_seconds}, {"bvh", bvh_seconds},
                            {"upload", upload_seconds}, {"render", render_seconds},
                            {"write", write_seconds}};
        stats["kernels"] = kernel_times_json(context);
        stats["rays"] = rays;
        stats["mrays_per_second"] = kernel_seconds > 0.0 ? rays / kernel_seconds * 1e-6 : 0.0;
        stats["nonfinite_samples"] = nonfinite;
        stats["first_nonfinite_pixel"] = first_nonfinite_pixel;
        nlohmann::json builds = nlohmann::json::array();
        for (const ProgramBuildReport& build : context.program_builds()) {
            builds.push_back({{"program", build.entry},
                              {"seconds", build.seconds},
                              {"from_cache", build.from_cache}});
        }
        stats["program_builds"] = builds;
        stats["bvh"] = {{"nodes", bvh.nodes.size()},
                        {"leaves", bvh.leaf_count},
                        {"depth", bvh.depth},
                        {"bytes", bvh.device_bytes()}};
        write_file_atomically(stats_path, stats.dump(2) + "\n");
    }
    return 0;
}

}  // namespace rc
