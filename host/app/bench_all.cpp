// `radcache bench all`: every kernel family's throughput on every OpenCL device, side by side in
// one run (DESIGN.md §7), with Embree's native intersector on the same rays as the anchor.
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

#include "app/bench_together.h"
#include "app/commands.h"
#include "app/device_options.h"
#include "app/path_tracing_bench.h"
#include "app/ray_bench.h"
#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "device/device_features.h"
#include "device/device_list.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/sdrc/sdrc_cache.h"
#include "scene/camera.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "util/cli.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/timing.h"

namespace rc {
namespace {

// One measured figure of one device.
struct Figure {
    std::string key;    // JSON name
    std::string label;  // table row
    double value = 0.0;
    double embree = 0.0;  // the anchor on the same work, 0 when there is none
};

struct DeviceResult {
    DeviceInfo device;
    std::vector<Figure> figures;
    unsigned embree_threads = 0;
    std::string error;  // why this device could not be measured
};

// Device seconds of the named kernels accumulated since `before`.
double kernel_seconds_since(const Context& context, const std::map<std::string, KernelTime>& before,
                            const std::vector<std::string>& kernels) {
    double seconds = 0.0;
    for (const std::string& name : kernels) {
        const auto now = context.kernel_times().find(name);
        if (now == context.kernel_times().end()) {
            continue;
        }
        const auto then = before.find(name);
        seconds += now->second.seconds - (then == before.end() ? 0.0 : then->second.seconds);
    }
    return seconds;
}

// Irradiance caching on glossy-box (the shipped scene with glossy lobes: the benchmark's own
// scene may have none) with a glossy cache serving the specular lobes, at the benchmark's size up
// to 128², 2 camera samples, the diffuse records with 256 rays and one level (not what is
// measured), after a 16² warm-up. Each render makes a Cache with its Options at their defaults
// but for the scene's path depths, and `keep(cache)` reads its statistics; returns the kernel
// times before the timed render.
template <class Cache, class Options, class Keep>
std::map<std::string, KernelTime> render_glossy_box(Context& context, int width, int height,
                                                    const Keep& keep) {
    const Scene scene = load_scene(shipped_scene("glossy-box"));
    const Bvh bvh = build_bvh(scene.mesh, context.bvh_layout());
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    const FrameScene frame{context, scene, device_bvh, device_scene};
    std::map<std::string, KernelTime> before;
    for (int pass = 0; pass < 2; ++pass) {
        before = context.kernel_times();
        PipelineSettings ic;
        ic.width = pass == 0 ? 16 : std::min(width, 128);
        ic.height = pass == 0 ? 16 : std::min(height, 128);
        ic.spp = 2;
        ic.rays = 256;
        ic.bounces = 1;
        ic.max_depth = scene.render.max_depth;
        ic.rr_depth = scene.render.rr_depth;
        ic.records_overlay = false;
        Options options;
        options.max_depth = ic.max_depth;
        options.rr_depth = ic.rr_depth;
        const auto cache = std::make_unique<Cache>(frame, options);
        CachePipeline(frame, {.lobes = cache.get()}).render(ic);
        keep(*cache);
    }
    return before;
}

// Radiance caching at its defaults (render_glossy_box): SH coefficients projected per second of
// the projection kernel (one coefficient of one channel from one hemisphere cell each) and record
// reflections interpolated per second of the glossy buffer's kernel (a rotation and three dot
// products each).
void bench_radiance_cache(Context& context, int width, int height, DeviceResult* result) {
    RadianceCacheStats stats;
    const auto before = render_glossy_box<RadianceCache, RadianceCacheOptions>(
        context, width, height, [&](const RadianceCache& cache) { stats = cache.stats(); });
    const double project_seconds = kernel_seconds_since(context, before, {"rc_record_project"});
    const double coefficients = static_cast<double>(stats.records) * stats.strata_m *
                                stats.strata_n * 3.0 * stats.order * stats.order;
    result->figures.push_back({"sh_coefficients_per_second", "RC SH coefficients projected/s (M)",
                               coefficients / project_seconds * 1e-6, 0.0});
    const double splat_seconds = kernel_seconds_since(context, before, {"rc_glossy_splat"});
    result->figures.push_back({"rc_reflections_per_second", "RC records interpolated/s (M)",
                               static_cast<double>(stats.reflections) / splat_seconds * 1e-6, 0.0});
}

// SDRC at its defaults (render_glossy_box): L-tree range queries per second of the interpolation
// kernel (one record's L-tree searched for one direction each) and lobe directions interpolated
// per second.
void bench_sdrc(Context& context, int width, int height, DeviceResult* result) {
    SdrcStats stats;
    const auto before = render_glossy_box<SdrcCache, SdrcOptions>(
        context, width, height, [&](const SdrcCache& cache) { stats = cache.stats(); });
    const double seconds = kernel_seconds_since(context, before, {"sdrc_interpolate"});
    result->figures.push_back({"ltree_queries_per_second", "SDRC L-tree range queries/s (M)",
                               static_cast<double>(stats.range_queries) / seconds * 1e-6, 0.0});
    result->figures.push_back({"sdrc_directions_per_second", "SDRC directions interpolated/s (M)",
                               static_cast<double>(stats.directions) / seconds * 1e-6, 0.0});
}

DeviceResult bench_device(const DeviceInfo& device, ContextOptions context_options,
                          const Scene& scene, int width, int height, int pt_spp, int repeats,
                          uint64_t photons) {
    DeviceResult result;
    result.device = device;
    context_options.device_spec = device.spec();
    Context context(context_options);
    refuse_loop_capped_device(context);
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    result.embree_threads = std::min(hardware, std::max(1u, device.compute_units));

    // Traversal: camera rays (coherent) and their diffuse bounces (incoherent), device against
    // Embree on the very same rays.
    RayBench rays(context, scene, result.embree_threads, repeats);
    const std::vector<shared::Ray> coherent =
        rays.tracer().camera_rays(camera_params(scene.camera, width, height));
    const std::vector<shared::Ray> incoherent = rays.tracer().diffuse_bounce_rays(coherent, 1);
    for (const RayCaseResult& r : rays.run(coherent, incoherent)) {
        std::string label = r.name;
        std::replace(label.begin(), label.end(), '_', ' ');
        result.figures.push_back(
            {r.name + "_mrays", label + " Mrays/s", r.device_mrays, r.embree_mrays});
    }
    const DeviceScene device_scene(context, scene);

    // Path tracing: a one-pass warm-up (kernel build, code generation), then the timed passes.
    const PathTracingTime pt =
        time_path_tracing({context, scene, rays.device_bvh(), device_scene}, width, height, pt_spp);
    const double paths = static_cast<double>(width) * height * pt_spp;
    result.figures.push_back(
        {"path_samples_per_second", "path samples/s (M)", paths / pt.seconds * 1e-6, 0.0});
    result.figures.push_back({"path_tracing_mrays", "path tracing Mrays/s",
                              static_cast<double>(pt.stats.rays) / pt.seconds * 1e-6, 0.0});

    // Irradiance caching at its defaults, one camera sample per pixel: hemisphere samples (a
    // ray and its path-traced continuation each) of the record kernels, and camera samples of
    // the render pass. A small warm-up render first.
    CachePipeline cache({context, scene, rays.device_bvh(), device_scene});
    PipelineSettings ic;
    ic.width = std::min(width, 64);
    ic.height = std::min(height, 64);
    ic.spp = 1;
    ic.max_depth = scene.render.max_depth;
    ic.rr_depth = scene.render.rr_depth;
    ic.records_overlay = false;
    cache.render(ic);
    auto before = context.kernel_times();
    ic.width = width;
    ic.height = height;
    PipelineStats ic_stats;
    cache.render(ic, &ic_stats);
    const double record_seconds =
        kernel_seconds_since(context, before, {"ic_record_cells", "ic_record_reduce"});
    const double hemisphere_samples =
        static_cast<double>(ic_stats.records) * ic_stats.strata_m * ic_stats.strata_n;
    result.figures.push_back({"hemisphere_samples_per_second", "hemisphere samples/s (M)",
                              hemisphere_samples / record_seconds * 1e-6, 0.0});
    result.figures.push_back({"records_per_second", "IC records/s (k)",
                              static_cast<double>(ic_stats.records) / record_seconds * 1e-3, 0.0});
    const double shade_seconds = kernel_seconds_since(context, before, {"ic_shade"});
    result.figures.push_back({"shade_samples_per_second", "IC render pass samples/s (M)",
                              static_cast<double>(width) * height / shade_seconds * 1e-6, 0.0});

    // Interpolation at the same camera samples from the same records, side by side: radiance
    // cache splatting (screen tiles binned on the host, ic_splat) and the world-space gather
    // (record grid built on the host, ic_gather), each timed on the wall clock, host work and
    // uploads included.
    const std::vector<shared::GBufferSample> samples = cache.camera_samples();
    // Alternating rounds, so both meet the same machine load; the median round of each.
    std::vector<double> splat_rounds;
    std::vector<double> gather_rounds;
    for (int r = 0; r < 2 * repeats + 1; ++r) {
        for (std::vector<double>* rounds : {&splat_rounds, &gather_rounds}) {
            context.finish();
            const auto start = SteadyClock::now();
            if (rounds == &splat_rounds) {
                cache.splat(cache.store(), cache.camera(), ic.spp, samples);
            } else {
                cache.gather(cache.store(), samples);
            }
            rounds->push_back(static_cast<double>(samples.size()) / seconds_since(start) * 1e-6);
        }
    }
    for (std::vector<double>* rounds : {&splat_rounds, &gather_rounds}) {
        std::nth_element(rounds->begin(), rounds->begin() + repeats, rounds->end());
    }
    result.figures.push_back({"splat_samples_per_second", "IC splat samples/s (M)",
                              splat_rounds[static_cast<size_t>(repeats)], 0.0});
    result.figures.push_back({"gather_samples_per_second", "IC gather samples/s (M)",
                              gather_rounds[static_cast<size_t>(repeats)], 0.0});

    // Photon tracing into the irradiance vector grid at its automatic size (a small warm-up
    // first): photons/s, each traced through its bounces and deposited at every face crossing.
    IrradianceVectorGrid grid({context, scene, rays.device_bvh(), device_scene});
    IvgOptions ivg;
    ivg.max_depth = scene.render.max_depth;
    ivg.rr_depth = scene.render.rr_depth;
    ivg.photons = 1024;
    grid.build(ivg);
    before = context.kernel_times();
    ivg.photons = photons;
    IvgStats grid_stats;
    grid.build(ivg, &grid_stats);
    const double photon_seconds = kernel_seconds_since(context, before, {"ivg_trace_photons"});
    result.figures.push_back({"photons_per_second", "photons/s (M)",
                              static_cast<double>(grid_stats.photons) / photon_seconds * 1e-6,
                              0.0});
    result.figures.push_back({"photon_crossings_per_second", "photon face crossings/s (M)",
                              static_cast<double>(grid_stats.crossings) / photon_seconds * 1e-6,
                              0.0});
    bench_radiance_cache(context, width, height, &result);
    bench_sdrc(context, width, height, &result);
    return result;
}

std::vector<OptionSpec> bench_all_options() {
    return with_device_options({
        {"--scene", "", "FILE", "scene (default scenes/cornell-box/scene.json)"},
        OptionSpec{"--width", "", "N", "image width (default 512)"}.integers(1, 1 << 14),
        OptionSpec{"--height", "", "N", "image height (default 512)"}.integers(1, 1 << 14),
        OptionSpec{"--spp", "", "N", "timed path-tracing samples per pixel (default 4)"}.integers(
            1, 1 << 16),
        OptionSpec{"--repeat", "", "N",
                   "timed repetitions per ray case, median reported (default 3)"}
            .integers(1, 1000),
        OptionSpec{"--photons", "", "N",
                   "photons traced into the irradiance vector grid (default 2^18)"}
            .integers(1, 1LL << 31),
        {"--json", "", "FILE", "also write the results as JSON"},
    });
}

int bench_all(const ParsedArguments& arguments) {
    if (!arguments.positionals().empty()) {
        throw Error("unexpected argument '" + arguments.positionals()[0] + "'", kExitUsage);
    }
    const std::string scene_path =
        arguments.has("--scene") ? arguments.value("--scene") : shipped_scene("cornell-box");
    check_bench_files(arguments, {scene_path});
    const int width = static_cast<int>(arguments.integer("--width", 512));
    const int height = static_cast<int>(arguments.integer("--height", 512));
    const int spp = static_cast<int>(arguments.integer("--spp", 4));
    const int repeats = static_cast<int>(arguments.integer("--repeat", 3));
    const uint64_t photons = static_cast<uint64_t>(arguments.integer("--photons", 1 << 18));
    const std::filesystem::path json_path = arguments.value("--json");
    if (!json_path.empty()) {
        check_writable_parent(json_path, "--json");
    }

    const ContextOptions options = context_options(arguments);
    const std::vector<DeviceInfo> all = list_devices();
    std::vector<DeviceInfo> devices;
    if (arguments.has("--device")) {
        devices = select_devices(all, options.device_spec);
    } else {
        devices = all;
    }
    const Scene scene = load_scene(scene_path);

    std::vector<DeviceResult> results;
    for (const DeviceInfo& device : devices) {
        std::fprintf(stderr, "bench all: %s %s\n", device.spec().c_str(), device.name.c_str());
        try {
            results.push_back(
                bench_device(device, options, scene, width, height, spp, repeats, photons));
        } catch (const Error& e) {
            DeviceResult failed;
            failed.device = device;
            failed.error = e.what();
            std::fprintf(stderr, "bench all: %s failed: %s\n", device.spec().c_str(), e.what());
            results.push_back(failed);
        }
    }

    // The table: one row per figure, one column per device, Embree's anchor last.
    std::printf("scene %s at %dx%d (%d spp path tracing, irradiance cache defaults at 1 spp)\n",
                scene_path.c_str(), width, height, spp);
    std::printf("%-36s", "figure");
    for (const DeviceResult& r : results) {
        std::printf(" %22.22s", (r.device.spec() + " " + r.device.name).c_str());
    }
    std::printf(" %22s\n", "Embree (same rays)");
    const DeviceResult* measured = nullptr;
    for (const DeviceResult& r : results) {
        if (r.error.empty()) {
            measured = &r;
            break;
        }
    }
    if (measured != nullptr) {
        for (size_t f = 0; f < measured->figures.size(); ++f) {
            std::printf("%-36s", measured->figures[f].label.c_str());
            for (const DeviceResult& r : results) {
                if (r.error.empty()) {
                    std::printf(" %22.3f", r.figures[f].value);
                } else {
                    std::printf(" %22s", "failed");
                }
            }
            if (measured->figures[f].embree > 0.0) {
                std::printf(" %15.3f (%2u th)\n", measured->figures[f].embree,
                            measured->embree_threads);
            } else {
                std::printf(" %22s\n", "-");
            }
        }
    }

    std::vector<TogetherFigure> together;
    if (devices.size() > 1) {
        std::fprintf(stderr, "bench all: %zu devices together\n", devices.size());
        together =
            bench_devices_together(devices, options, scene, {width, height, spp, photons, repeats});
        print_together(devices, together);
    }

    if (!json_path.empty()) {
        nlohmann::json report;
        report["scene"] = scene_path;
        report["resolution"] = {width, height};
        report["pt_spp"] = spp;
        report["devices"] = nlohmann::json::array();
        for (const DeviceResult& r : results) {
            nlohmann::json entry = {{"device", r.device.name},
                                    {"spec", r.device.spec()},
                                    {"platform", r.device.platform_name},
                                    {"type", r.device.type},
                                    {"compute_units", r.device.compute_units},
                                    {"embree_threads", r.embree_threads}};
            if (!r.error.empty()) {
                entry["error"] = r.error;
            }
            for (const Figure& f : r.figures) {
                entry[f.key] = f.value;
                if (f.embree > 0.0) {
                    entry["embree_" + f.key] = f.embree;
                }
            }
            report["devices"].push_back(entry);
        }
        if (!together.empty()) {
            report["together"] = together_json(devices, together);
        }
        write_file_atomically(json_path, report.dump(2) + "\n");
    }
    const bool any_failed = std::any_of(results.begin(), results.end(),
                                        [](const DeviceResult& r) { return !r.error.empty(); });
    return any_failed ? 1 : 0;
}

}  // namespace

CommandSpec bench_all_command() {
    return {
        .name = "bench all",
        .summary = "every kernel family on every device, side by side",
        .description =
            "Every kernel family on every OpenCL device (or those --device names), side by\n"
            "side: traversal Mrays/s (coherent and incoherent, closest and any hit) with Embree's\n"
            "rtcIntersect1/rtcOccluded1 on the same rays as the anchor, path samples/s, "
            "irradiance\n"
            "cache hemisphere samples/s and records/s, render-pass, splat and gather samples/s, "
            "and "
            "photons/s\n"
            "into the irradiance vector grid, radiance caching's SH coefficients projected/s and "
            "records\n"
            "interpolated/s, SDRC's L-tree range queries/s and directions interpolated/s (on "
            "glossy-box). Device\n"
            "kernel time from profiling events; kernels are built and warmed up first. With "
            "several devices,\n"
            "whole pt and ic renders and grid builds are also timed on the wall clock on each "
            "device "
            "alone and on all\n"
            "of them together (their work split as render --device all splits it).",
        .options = bench_all_options(),
        .run = bench_all};
}

}  // namespace rc
