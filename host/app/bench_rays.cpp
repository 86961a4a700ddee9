// `radcache bench rays`: device traversal throughput against Embree's rtcIntersect1 /
// rtcOccluded1 on the very same rays and triangles, measured side by side in one run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "app/commands.h"
#include "app/device_options.h"
#include "app/ray_bench.h"
#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "bvh/embree_scene.h"
#include "device/device_features.h"
#include "scene/camera.h"
#include "scene/generated_meshes.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

constexpr const char* kDenseSceneName = "generated:sphere-grid";

std::vector<OptionSpec> bench_rays_specs() {
    return with_device_options({
        {"--scene", "", "FILE",
         "scene to measure (repeatable; default: scenes/cornell-box/scene.json and the generated "
         "512k-triangle sphere grid, named " +
             std::string(kDenseSceneName) + ")",
         true},
        {"--json", "", "FILE", "also write the results as JSON"},
        OptionSpec{"--width", "", "N", "camera rays across (default 1024)"}.integers(1, 1 << 14),
        OptionSpec{"--height", "", "N", "camera rays down (default: by the scene camera's aspect)"}
            .integers(1, 1 << 14),
        OptionSpec{"--repeat", "", "N", "timed repetitions per case, median reported (default 3)"}
            .integers(1, 1000),
        OptionSpec{"--threads", "", "N", "Embree threads (default: the device's compute units)"}
            .integers(1, 4096),
        OptionSpec{"--seed", "", "N", "seed of the bounce directions (default 1)"}.integers(
            0, 1LL << 62),
    });
}

// One layout's figures on one scene: the BVH's size and the four cases.
nlohmann::json layout_report(const Bvh& bvh, const std::vector<RayCaseResult>& results) {
    nlohmann::json entry;
    entry["nodes"] = bvh.node_count();
    entry["leaves"] = bvh.leaf_count;
    entry["depth"] = bvh.depth;
    entry["node_bytes"] = bvh.node_bytes();
    entry["leaf_bytes"] = bvh.leaf_bytes();
    entry["build_seconds"] = bvh.build_seconds;
    for (const RayCaseResult& r : results) {
        entry[r.name] = {{"rays", r.rays},
                         {"device_mrays", r.device_mrays},
                         {"embree_mrays", r.embree_mrays},
                         {"ratio", r.ratio_per_thread},
                         {"agreement", r.agreement}};
    }
    return entry;
}

void print_layout(const std::string& layout, const Bvh& bvh) {
    std::printf("%-6s %9zu nodes %8.2f MB, %9zu leaves %8.2f MB, depth %2u, built in %.2f s\n",
                layout.c_str(), bvh.node_count(), static_cast<double>(bvh.node_bytes()) * 1e-6,
                bvh.leaf_count, static_cast<double>(bvh.leaf_bytes()) * 1e-6, bvh.depth,
                bvh.build_seconds);
}

// The layouts --bvh names, else both (one context each: a program is built for one layout).
std::vector<BvhLayout> measured_layouts(const ContextOptions& options) {
    if (options.bvh_layout) {
        return {*options.bvh_layout};
    }
    return {std::begin(kBvhLayouts), std::end(kBvhLayouts)};
}

int bench_rays(const ParsedArguments& arguments) {
    if (!arguments.positionals().empty()) {
        throw Error("unexpected argument '" + arguments.positionals()[0] + "'", kExitUsage);
    }
    std::vector<std::string> scenes = arguments.values("--scene");
    if (scenes.empty()) {
        scenes = {shipped_scene("cornell-box"), kDenseSceneName};
    }
    check_bench_files(arguments, scenes);
    const std::filesystem::path json_path = arguments.value("--json");
    const int width = static_cast<int>(arguments.integer("--width", 1024));
    const int repeats = static_cast<int>(arguments.integer("--repeat", 3));
    const uint64_t seed = static_cast<uint64_t>(arguments.integer("--seed", 1));

    std::vector<std::unique_ptr<Context>> contexts;
    for (BvhLayout layout : measured_layouts(context_options(arguments))) {
        ContextOptions options = context_options(arguments);
        options.bvh_layout = layout;
        contexts.push_back(std::make_unique<Context>(options));
        refuse_loop_capped_device(*contexts.back());
    }
    const DeviceInfo& device = contexts.front()->device();
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const unsigned threads = static_cast<unsigned>(
        arguments.integer("--threads", std::min(hardware, std::max(1u, device.compute_units))));

    nlohmann::json report = nlohmann::json::array();
    for (const std::string& scene_name : scenes) {
        const Scene scene =
            scene_name == kDenseSceneName ? make_sphere_grid_scene() : load_scene(scene_name);
        const int height = static_cast<int>(arguments.integer(
            "--height",
            std::max(1, static_cast<int>(std::lround(static_cast<double>(width) *
                                                     scene.camera.height / scene.camera.width)))));
        std::printf("\nscene %s: %zu triangles, device %s (%u compute units), Embree %u threads\n",
                    scene_name.c_str(), scene.mesh.triangle_count(), device.name.c_str(),
                    device.compute_units, threads);
        nlohmann::json entry;
        entry["device"] = device.name;
        entry["scene"] = scene_name;
        entry["triangles"] = scene.mesh.triangle_count();
        entry["threads"] = threads;
        entry["device_compute_units"] = device.compute_units;
        std::vector<std::pair<std::string, std::vector<RayCaseResult>>> measured;
        for (const std::unique_ptr<Context>& context : contexts) {
            RayBench bench(*context, scene, threads, repeats);
            const std::vector<shared::Ray> coherent =
                bench.tracer().camera_rays(camera_params(scene.camera, width, height));
            const std::vector<shared::Ray> incoherent =
                bench.tracer().diffuse_bounce_rays(coherent, seed);
            const std::string layout = bvh_layout_name(context->bvh_layout());
            print_layout(layout, bench.bvh());
            measured.emplace_back(layout, bench.run(coherent, incoherent));
            entry["layouts"][layout] = layout_report(bench.bvh(), measured.back().second);
        }
        std::printf("%-20s %-6s %10s %14s %14s %12s %10s\n", "case", "layout", "rays",
                    "device Mray/s", "Embree Mray/s", "ratio/thread", "agree");
        for (size_t c = 0; c < measured.front().second.size(); ++c) {
            for (const auto& [layout, results] : measured) {
                const RayCaseResult& r = results[c];
                std::printf("%-20s %-6s %10zu %14.2f %14.2f %12.3f %9.4f%%\n", r.name.c_str(),
                            layout.c_str(), r.rays, r.device_mrays, r.embree_mrays,
                            r.ratio_per_thread, 100.0 * r.agreement);
            }
        }
        report.push_back(entry);
    }
    if (!json_path.empty()) {
        write_file_atomically(json_path, report.dump(2) + "\n");
    }
    return 0;
}

}  // namespace

CommandSpec bench_rays_command() {
    return {
        .name = "bench rays",
        .summary = "traversal throughput against Embree",
        .description =
            "Measures closest-hit and any-hit throughput (Mrays/s) of the device traversal on\n"
            "coherent (camera) and incoherent (diffuse bounce) rays, in each BVH layout (bvh4 and\n"
            "wide; --bvh picks one), and Embree's rtcIntersect1 / rtcOccluded1 on the same rays\n"
            "right after each; ratio = device / Embree per thread (device threads = compute\n"
            "units). 'agree' is the fraction of rays with the same answer.",
        .options = bench_rays_specs(),
        .run = bench_rays};
}

}  // namespace rc
