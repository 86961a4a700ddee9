#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/commands.h"
#include "app/device_options.h"
#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "image/image_io.h"
#include "methods/normals.h"
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

std::vector<OptionSpec> render_option_specs() {
    std::vector<OptionSpec> specs = {
        {"--output", "-o", "FILE", "output image: .exr, .hdr, .pfm or .png (default out.png)"},
        {"--method", "", "NAME", "rendering method: normals (the geometry preview; default)"},
        {"--width", "", "N", "image width in pixels (default: the scene's)"},
        {"--height", "", "N", "image height in pixels (default: the scene's)"},
        {"--spp", "", "N", "samples per pixel (default 1)"},
        {"--seed", "", "N", "random seed (default 0)"},
        {"--exposure", "", "STOPS", "exposure applied before 8-bit encoding (default 0)"},
        {"--stats", "", "FILE", "write timings and counts as JSON"},
        {"--quiet", "-q", "", "print nothing but errors"},
    };
    for (OptionSpec& spec : device_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
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
    const std::string method = arguments.value("--method", "normals");
    if (method != "normals") {
        throw Error("--method: unknown method '" + method + "' (implemented: normals)", kExitUsage);
    }
    const std::filesystem::path output = arguments.value("--output", "out.png");
    check_output_path(output);
    const std::filesystem::path stats_path = arguments.value("--stats");
    if (!stats_path.empty()) {
        const std::filesystem::path dir =
            stats_path.parent_path().empty() ? "." : stats_path.parent_path();
        if (!std::filesystem::is_directory(dir)) {
            throw Error(stats_path.string() + ": directory '" + dir.string() + "' does not exist",
                        kExitUsage);
        }
    }
    NormalsOptions options;
    options.width = static_cast<int>(arguments.integer("--width", 0, 1, 1 << 15));
    options.height = static_cast<int>(arguments.integer("--height", 0, 1, 1 << 15));
    options.samples_per_pixel = static_cast<unsigned>(arguments.integer("--spp", 1, 1, 1 << 20));
    options.seed = static_cast<uint64_t>(arguments.integer("--seed", 0, 0, (1LL << 62)));
    ImageWriteOptions write_options;
    write_options.exposure = static_cast<float>(arguments.number("--exposure", 0.0, -64.0, 64.0));

    const auto total_start = Clock::now();
    auto start = Clock::now();
    const Scene scene = load_scene(arguments.positionals()[0]);
    const double load_seconds = seconds_since(start);
    if (scene.dropped_degenerate > 0) {
        log_note("dropped " + std::to_string(scene.dropped_degenerate) + " degenerate triangles");
    }

    start = Clock::now();
    const Bvh bvh = build_bvh(scene.mesh);
    const double bvh_seconds = seconds_since(start);

    start = Clock::now();
    Context context(context_options(arguments));
    const DeviceBvh device_bvh(context, bvh);
    NormalsMethod renderer(context, scene, device_bvh);
    const double setup_seconds = seconds_since(start);
    log_note("device " + context.device().name + "; " +
             std::to_string(scene.mesh.triangle_count()) + " triangles");

    start = Clock::now();
    const Image image = renderer.render(options);
    const double render_seconds = seconds_since(start);

    start = Clock::now();
    write_image(output, image, write_options);
    const double write_seconds = seconds_since(start);
    log_note("wrote " + output.string() + " (" + std::to_string(image.width) + "x" +
             std::to_string(image.height) + ", " + std::to_string(options.samples_per_pixel) +
             " spp) in " + std::to_string(seconds_since(total_start)) + " s");

    if (!stats_path.empty()) {
        nlohmann::json stats;
        stats["method"] = method;
        stats["device"] = context.device().name;
        stats["scene"] = scene.path.string();
        stats["triangles"] = scene.mesh.triangle_count();
        stats["dropped_degenerate_triangles"] = scene.dropped_degenerate;
        stats["resolution"] = {image.width, image.height};
        stats["spp"] = options.samples_per_pixel;
        stats["seconds"] = {{"total", seconds_since(total_start)},
                            {"load", load_seconds},
                            {"bvh", bvh_seconds},
                            {"device_setup", setup_seconds},
                            {"render", render_seconds},
                            {"write", write_seconds}};
        nlohmann::json kernels = nlohmann::json::object();
        for (const auto& [name, time] : context.kernel_times()) {
            kernels[name] = {
                {"seconds", time.seconds}, {"launches", time.launches}, {"items", time.items}};
        }
        stats["kernels"] = kernels;
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
