// `radcache bench rays`: device traversal throughput against Embree's rtcIntersect1 /
// rtcOccluded1 on the very same rays and triangles, measured side by side in one run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "app/cli.h"
#include "app/commands.h"
#include "app/device_options.h"
#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "bvh/embree_scene.h"
#include "scene/camera.h"
#include "scene/generated_meshes.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

constexpr const char* kDenseSceneName = "generated:sphere-grid";

struct CaseResult {
    std::string name;
    size_t rays = 0;
    double device_mrays = 0.0;
    double embree_mrays = 0.0;
    double ratio_per_thread = 0.0;
    double agreement = 0.0;  // fraction of rays with the same answer
};

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

class RayBench {
   public:
    RayBench(Context& context, const Scene& scene, unsigned embree_threads, int repeats)
        : context_(context),
          bvh_(build_bvh(scene.mesh)),
          device_bvh_(context, bvh_),
          tracer_(context, device_bvh_),
          embree_(scene.mesh),
          threads_(embree_threads),
          repeats_(repeats) {}

    DeviceTracer& tracer() { return tracer_; }

    std::vector<CaseResult> run(const std::vector<shared::Ray>& coherent,
                                const std::vector<shared::Ray>& incoherent) {
        std::vector<CaseResult> results;
        for (const auto& [name, rays] :
             {std::pair{"coherent", &coherent}, std::pair{"incoherent", &incoherent}}) {
            results.push_back(closest_case(std::string(name) + "_closest", *rays));
            results.push_back(any_case(std::string(name) + "_any", *rays));
        }
        return results;
    }

   private:
    double device_seconds(const std::string& kernel, const std::function<void()>& launch) {
        launch();  // warm-up: the first launch may generate code for the work-group size
        std::vector<double> times;
        for (int r = 0; r < repeats_; ++r) {
            const double before = context_.kernel_times().at(kernel).seconds;
            launch();
            times.push_back(context_.kernel_times().at(kernel).seconds - before);
        }
        return median(times);
    }

    double embree_seconds(const std::function<void()>& trace) {
        trace();
        std::vector<double> times;
        for (int r = 0; r < repeats_; ++r) {
            const auto start = std::chrono::steady_clock::now();
            trace();
            times.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        return median(times);
    }

    CaseResult finish(const std::string& name, size_t rays, double device_s, double embree_s,
                      size_t agreeing) {
        CaseResult result;
        result.name = name;
        result.rays = rays;
        result.device_mrays = static_cast<double>(rays) / device_s * 1e-6;
        result.embree_mrays = static_cast<double>(rays) / embree_s * 1e-6;
        const double device_threads = std::max(1u, context_.device().compute_units);
        result.ratio_per_thread = (result.device_mrays / device_threads) /
                                  (result.embree_mrays / static_cast<double>(threads_));
        result.agreement = static_cast<double>(agreeing) / static_cast<double>(rays);
        return result;
    }

    CaseResult closest_case(const std::string& name, const std::vector<shared::Ray>& rays) {
        const Buffer<shared::Ray> ray_buffer(context_, rays, "bench_rays");
        Buffer<shared::Hit> hit_buffer(context_, rays.size(), "bench_hits");
        const double device_s =
            device_seconds("trace_closest", [&] { tracer_.trace_closest(ray_buffer, hit_buffer); });
        std::vector<shared::Hit> embree_hits;
        const double embree_s =
            embree_seconds([&] { embree_.intersect(rays, embree_hits, threads_); });
        const std::vector<shared::Hit> device_hits = hit_buffer.download();
        size_t agreeing = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            agreeing += same_closest_hit(device_hits[i], embree_hits[i]) ? 1 : 0;
        }
        return finish(name, rays.size(), device_s, embree_s, agreeing);
    }

    CaseResult any_case(const std::string& name, const std::vector<shared::Ray>& rays) {
        const Buffer<shared::Ray> ray_buffer(context_, rays, "bench_rays");
        Buffer<unsigned> occluded_buffer(context_, rays.size(), "bench_occluded");
        const double device_s =
            device_seconds("trace_any", [&] { tracer_.trace_any(ray_buffer, occluded_buffer); });
        std::vector<unsigned> embree_occluded;
        const double embree_s =
            embree_seconds([&] { embree_.occluded(rays, embree_occluded, threads_); });
        const std::vector<unsigned> device_occluded = occluded_buffer.download();
        size_t agreeing = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            agreeing += device_occluded[i] == embree_occluded[i] ? 1 : 0;
        }
        return finish(name, rays.size(), device_s, embree_s, agreeing);
    }

    Context& context_;
    Bvh bvh_;
    DeviceBvh device_bvh_;
    DeviceTracer tracer_;
    EmbreeScene embree_;
    unsigned threads_;
    int repeats_;
};

std::vector<OptionSpec> bench_rays_specs() {
    std::vector<OptionSpec> specs = {
        {"--scene", "", "FILE",
         "scene to measure (repeatable; default: scenes/cornell-box/scene.json and the generated "
         "512k-triangle sphere grid, named " +
             std::string(kDenseSceneName) + ")",
         true},
        {"--json", "", "FILE", "also write the results as JSON"},
        {"--width", "", "N", "camera rays across (default 1024)"},
        {"--height", "", "N", "camera rays down (default: by the scene camera's aspect)"},
        {"--repeat", "", "N", "timed repetitions per case, median reported (default 3)"},
        {"--threads", "", "N", "Embree threads (default: the device's compute units)"},
        {"--seed", "", "N", "seed of the bounce directions (default 1)"},
    };
    for (OptionSpec& spec : device_option_specs()) {
        specs.push_back(std::move(spec));
    }
    return specs;
}

std::string default_cornell_box() {
    for (const char* candidate :
         {"scenes/cornell-box/scene.json", RADCACHE_SOURCE_DIR "/scenes/cornell-box/scene.json"}) {
        if (std::filesystem::is_regular_file(candidate)) {
            return candidate;
        }
    }
    throw Error("cannot find scenes/cornell-box/scene.json; pass --scene", kExitUsage);
}

}  // namespace

int run_bench_rays(const std::vector<std::string>& args) {
    const std::vector<OptionSpec> specs = bench_rays_specs();
    const ParsedArguments arguments = parse_arguments("radcache bench rays", args, specs);
    if (arguments.has("--help")) {
        std::cout << format_help(
            "radcache bench rays [options]",
            "Measures closest-hit and any-hit throughput (Mrays/s) of the device traversal on\n"
            "coherent (camera) and incoherent (diffuse bounce) rays, and Embree's rtcIntersect1 /\n"
            "rtcOccluded1 on the same rays; ratio = device / Embree per thread (device threads =\n"
            "compute units). 'agree' is the fraction of rays with the same answer.",
            specs);
        return 0;
    }
    if (!arguments.positionals().empty()) {
        throw Error("unexpected argument '" + arguments.positionals()[0] + "'", kExitUsage);
    }
    std::vector<std::string> scenes = arguments.values("--scene");
    if (scenes.empty()) {
        scenes = {default_cornell_box(), kDenseSceneName};
    }
    const std::filesystem::path json_path = arguments.value("--json");
    const int width = static_cast<int>(arguments.integer("--width", 1024, 1, 1 << 14));
    const int repeats = static_cast<int>(arguments.integer("--repeat", 3, 1, 1000));
    const uint64_t seed = static_cast<uint64_t>(arguments.integer("--seed", 1, 0, 1LL << 62));

    Context context(context_options(arguments));
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const unsigned threads = static_cast<unsigned>(arguments.integer(
        "--threads", std::min(hardware, std::max(1u, context.device().compute_units)), 1, 4096));

    nlohmann::json report = nlohmann::json::array();
    for (const std::string& scene_name : scenes) {
        const Scene scene =
            scene_name == kDenseSceneName ? make_sphere_grid_scene() : load_scene(scene_name);
        const int height = static_cast<int>(arguments.integer(
            "--height",
            std::max(1, static_cast<int>(std::lround(static_cast<double>(width) *
                                                     scene.camera.height / scene.camera.width))),
            1, 1 << 14));
        RayBench bench(context, scene, threads, repeats);
        const std::vector<shared::Ray> coherent =
            bench.tracer().camera_rays(camera_params(scene.camera, width, height));
        const std::vector<shared::Ray> incoherent =
            bench.tracer().diffuse_bounce_rays(coherent, seed);
        const std::vector<CaseResult> results = bench.run(coherent, incoherent);

        std::printf("\nscene %s: %zu triangles, device %s (%u compute units), Embree %u threads\n",
                    scene_name.c_str(), scene.mesh.triangle_count(), context.device().name.c_str(),
                    context.device().compute_units, threads);
        std::printf("%-20s %10s %14s %14s %12s %10s\n", "case", "rays", "device Mray/s",
                    "Embree Mray/s", "ratio/thread", "agree");
        nlohmann::json entry;
        entry["device"] = context.device().name;
        entry["scene"] = scene_name;
        entry["triangles"] = scene.mesh.triangle_count();
        entry["threads"] = threads;
        entry["device_compute_units"] = context.device().compute_units;
        for (const CaseResult& r : results) {
            std::printf("%-20s %10zu %14.2f %14.2f %12.3f %9.4f%%\n", r.name.c_str(), r.rays,
                        r.device_mrays, r.embree_mrays, r.ratio_per_thread, 100.0 * r.agreement);
            entry[r.name] = {{"rays", r.rays},
                             {"device_mrays", r.device_mrays},
                             {"embree_mrays", r.embree_mrays},
                             {"ratio", r.ratio_per_thread},
                             {"agreement", r.agreement}};
        }
        report.push_back(entry);
    }
    if (!json_path.empty()) {
        write_file_atomically(json_path, report.dump(2) + "\n");
    }
    return 0;
}

}  // namespace rc
