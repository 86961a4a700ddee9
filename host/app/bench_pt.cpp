// `radcache bench pt`: path-tracing throughput (path samples/s, Mrays/s) and its ratio to the
// raw traversal throughput of the same device on the same scene, measured in the same run.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <thread>

#include "app/commands.h"
#include "app/device_options.h"
#include "app/path_tracing_bench.h"
#include "app/ray_bench.h"
#include "device/device_features.h"
#include "scene/camera.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::vector<OptionSpec> bench_pt_options() {
    return with_device_options({
        {"--scene", "", "FILE", "scene (default scenes/cornell-box/scene.json)"},
        OptionSpec{"--width", "", "N", "image width (default 512)"}.integers(1, 1 << 14),
        OptionSpec{"--height", "", "N", "image height (default 512)"}.integers(1, 1 << 14),
        OptionSpec{"--spp", "", "N", "timed samples per pixel (default 16)"}.integers(1, 1 << 16),
        {"--json", "", "FILE", "also write the results as JSON"},
    });
}

int bench_pt(const ParsedArguments& arguments) {
    const std::string scene_path =
        arguments.has("--scene") ? arguments.value("--scene") : shipped_scene("cornell-box");
    check_bench_files(arguments, {scene_path});
    const int width = static_cast<int>(arguments.integer("--width", 512));
    const int height = static_cast<int>(arguments.integer("--height", 512));
    const int spp = static_cast<int>(arguments.integer("--spp", 16));

    Context context(context_options(arguments));
    refuse_loop_capped_device(context);
    const Scene scene = load_scene(scene_path);
    const unsigned threads = std::min(std::max(1u, std::thread::hardware_concurrency()),
                                      std::max(1u, context.device().compute_units));

    // Path tracing: a one-pass warm-up (kernel build and work-group code generation), then the
    // timed render.
    RayBench rays(context, scene, threads, 3);
    const DeviceScene device_scene(context, scene);
    const PathTracingTime timed =
        time_path_tracing({context, scene, rays.device_bvh(), device_scene}, width, height, spp);
    const PathTracerStats& stats = timed.stats;
    const double seconds = timed.seconds;
    const double paths = static_cast<double>(width) * height * spp;

    // Raw traversal on the same scene: camera rays and their diffuse bounces.
    const std::vector<shared::Ray> coherent =
        rays.tracer().camera_rays(camera_params(scene.camera, width, height));
    const std::vector<shared::Ray> incoherent = rays.tracer().diffuse_bounce_rays(coherent, 1);
    double raw_incoherent = 0.0;
    for (const RayCaseResult& r : rays.run(coherent, incoherent)) {
        if (r.name == "incoherent_closest") {
            raw_incoherent = r.device_mrays;
        }
    }

    const double path_rate = paths / seconds;
    const double mrays = static_cast<double>(stats.rays) / seconds * 1e-6;
    std::printf("scene %s at %dx%d, %d spp, device %s\n", scene_path.c_str(), width, height, spp,
                context.device().name.c_str());
    std::printf("%-34s %12.3f\n", "path samples/s (millions)", path_rate * 1e-6);
    std::printf("%-34s %12.2f\n", "path tracing Mrays/s", mrays);
    std::printf("%-34s %12.2f\n", "rays per path", static_cast<double>(stats.rays) / paths);
    std::printf("%-34s %12.2f\n", "raw incoherent closest Mrays/s", raw_incoherent);
    std::printf("%-34s %12.3f\n", "ratio (shading cost)", mrays / raw_incoherent);
    if (arguments.has("--json")) {
        const nlohmann::json report = {{"device", context.device().name},
                                       {"scene", scene_path},
                                       {"resolution", {width, height}},
                                       {"spp", spp},
                                       {"kernel_seconds", seconds},
                                       {"path_samples_per_second", path_rate},
                                       {"mrays_per_second", mrays},
                                       {"rays_per_path", static_cast<double>(stats.rays) / paths},
                                       {"raw_incoherent_closest_mrays", raw_incoherent},
                                       {"ratio", mrays / raw_incoherent}};
        write_file_atomically(arguments.value("--json"), report.dump(2) + "\n");
    }
    return 0;
}

}  // namespace

CommandSpec bench_pt_command() {
    return {
        .name = "bench pt",
        .summary = "path-tracing throughput",
        .description =
            "Path-traces the scene and reports path samples/s and Mrays/s (device kernel time),\n"
            "and the ratio of its ray throughput to raw traversal of incoherent rays on the same\n"
            "device and scene (bench rays' incoherent_closest): what shading costs.",
        .options = bench_pt_options(),
        .run = bench_pt};
}

}  // namespace rc
