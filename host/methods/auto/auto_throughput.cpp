#include "methods/auto/auto_throughput.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "bvh/device_bvh.h"
#include "methods/auto/auto_pilot.h"
#include "methods/auto/auto_runs.h"
#include "scene/device_scene.h"
#include "scene/scene_files.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "util/log.h"
#include "util/timing.h"

namespace rc {
namespace {

// The built-in scene: a diffuse box open towards the camera, lit from above, a Phong 8 sphere
// (radiance caching's kind of lobe) and a Phong 60 sphere (SDRC's).
constexpr const char* kThroughputScene = R"({
    "camera": {"position": [0, 0, -3.4], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 42,
               "resolution": [128, 128]},
    "materials": {
        "white": {"type": "diffuse", "reflectance": [0.7, 0.7, 0.7]},
        "red": {"type": "diffuse", "reflectance": [0.6, 0.15, 0.1]},
        "satin": {"type": "phong", "diffuse": 0.4, "specular": 0.3, "exponent": 8},
        "copper": {"type": "phong", "diffuse": 0.2, "specular": 0.6, "exponent": 60}
    },
    "shapes": [
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"translate": [0, -1, 0]}]},
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"translate": [0, 1, 0]}]},
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 180}}, {"translate": [0, 0, 1]}]},
        {"type": "rectangle", "material": "red",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": -90}}, {"translate": [1, 0, 0]}]},
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 90}}, {"translate": [-1, 0, 0]}]},
        {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 12},
         "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                       {"translate": [0, 0.99, 0]}]},
        {"type": "sphere", "center": [-0.4, -0.6, 0.2], "radius": 0.38, "material": "copper"},
        {"type": "sphere", "center": [0.45, -0.7, -0.2], "radius": 0.28, "material": "satin"}
    ],
    "render": {"max_depth": 64, "rr_depth": 3}
})";

// Large enough that launches' fixed costs do not count (at 48 x 48 they tripled the camera
// samples' seconds per ray against a 256 x 256 render's).
constexpr int kSide = 128;
constexpr int kCameraSpp = 8;
// The fewer --ic-rays a caching method is measured at (the more: its default).
constexpr int kFewRays = 128;
constexpr int kPathTracerSpp = 16;
const char* const kCachingMethods[] = {"ic", "rc", "sdrc"};

std::filesystem::path throughput_file(const Context& context) {
    const std::filesystem::path& dir = context.options().cache_dir;
    if (dir.empty()) {
        return {};
    }
    const DeviceInfo& device = context.device();
    const std::string identity = device.platform_name + "|" + device.platform_version + "|" +
                                 device.name + "|" + device.driver_version;
    char name[64];
    std::snprintf(name, sizeof(name), "auto-throughput-%016zx.json",
                  std::hash<std::string>{}(identity));
    return dir / name;
}

nlohmann::json ray_cost_json(const CacheRayCost& cost) {
    return {{"ic_rays", {cost.rays[0], cost.rays[1]}},
            {"seconds_per_ray", {cost.seconds_per_ray[0], cost.seconds_per_ray[1]}}};
}

CacheRayCost ray_cost_of(const nlohmann::json& json) {
    CacheRayCost cost;
    for (int i = 0; i < 2; ++i) {
        cost.rays[i] = json.at("ic_rays").at(i).get<int>();
        cost.seconds_per_ray[i] = json.at("seconds_per_ray").at(i).get<double>();
    }
    return cost;
}

// The seconds a ray may plausibly take on any device: from 10^-12 (a thousand billion rays a
// second, beyond any device today) to 1 s. A cached figure outside (a hand-edited or damaged
// file) would plan absurd work, so the file is measured again.
bool plausible_ray_seconds(double seconds) {
    return std::isfinite(seconds) && seconds >= 1e-12 && seconds <= 1.0;
}

bool valid(const CacheRayCost& cost) {
    return cost.rays[0] > 0 && cost.rays[1] > cost.rays[0] &&
           plausible_ray_seconds(cost.seconds_per_ray[0]) &&
           plausible_ray_seconds(cost.seconds_per_ray[1]);
}

nlohmann::json throughput_json(const DeviceThroughput& t, const Context& context) {
    nlohmann::json cache = nlohmann::json::object();
    for (const auto& [method, cost] : t.cache_seconds_per_ray) {
        cache[method] = ray_cost_json(cost);
    }
    return {{"device", context.device().name},
            {"driver", context.device().driver_version},
            {"pt_seconds_per_ray", t.pt_seconds_per_ray},
            {"cache_seconds_per_ray", cache},
            {"camera_seconds_per_ray", t.camera_seconds_per_ray},
            {"table_seconds_per_material", t.table_seconds_per_material}};
}

bool read_throughput(const std::filesystem::path& file, DeviceThroughput* t) {
    std::ifstream in(file);
    if (!in) {
        return false;
    }
    try {
        const nlohmann::json json = nlohmann::json::parse(in);
        t->pt_seconds_per_ray = json.at("pt_seconds_per_ray").get<double>();
        for (const auto& [method, cost] : json.at("cache_seconds_per_ray").items()) {
            t->cache_seconds_per_ray[method] = ray_cost_of(cost);
        }
        t->camera_seconds_per_ray =
            json.at("camera_seconds_per_ray").get<std::map<std::string, double>>();
        t->table_seconds_per_material = json.at("table_seconds_per_material").get<double>();
    } catch (const nlohmann::json::exception&) {
        return false;  // unreadable: measured again and replaced
    }
    for (const char* method : kCachingMethods) {
        const auto cost = t->cache_seconds_per_ray.find(method);
        const auto camera = t->camera_seconds_per_ray.find(method);
        if (cost == t->cache_seconds_per_ray.end() || !valid(cost->second) ||
            camera == t->camera_seconds_per_ray.end() || !plausible_ray_seconds(camera->second)) {
            return false;
        }
    }
    // A material's BRDF tables: at most an hour.
    return plausible_ray_seconds(t->pt_seconds_per_ray) &&
           std::isfinite(t->table_seconds_per_material) && t->table_seconds_per_material >= 0.0 &&
           t->table_seconds_per_material <= 3600.0;
}

// Writes the figures unless another process has cached its own since (the first write wins, so
// that every plan on the device reads the same figures); a file that cannot be read (an older
// radcache's, without a figure this one needs) is replaced. Returns the figures the file holds.
DeviceThroughput cache_throughput(const DeviceThroughput& measured, const Context& context) {
    const std::filesystem::path& file = measured.file;
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    const std::filesystem::path temporary =
        file.string() + ".tmp" + std::to_string(static_cast<long>(::getpid()));
    {
        std::ofstream out(temporary);
        out << throughput_json(measured, context).dump(2) << "\n";
    }
    std::filesystem::create_hard_link(temporary, file, error);  // fails if the file exists
    DeviceThroughput cached = measured;
    if (error && !read_throughput(file, &cached)) {
        std::filesystem::rename(temporary, file, error);  // the unreadable file replaced
    }
    std::filesystem::remove(temporary, error);
    if (read_throughput(file, &cached)) {
        cached.measured_now = true;
        return cached;
    }
    return measured;
}

struct TimedFrame {
    FrameResult result;
    double seconds = 0.0;
};

TimedFrame timed_frame(const FrameScene& frame, const MethodRun& run, int side, int spp,
                       const FrameHooks& hooks) {
    MethodSettings settings;
    settings.width = side;
    settings.height = side;
    settings.spp = spp;
    settings.layers = {"beauty"};
    const std::unique_ptr<Method> method = make_method(run, settings);
    const auto start = SteadyClock::now();
    TimedFrame timed;
    timed.result = render_quietly(*method, frame, hooks);
    timed.seconds = seconds_since(start);
    return timed;
}

// The BRDF tables' seconds per glossy material, from an rc render whose tables are new (another
// --rc-max-error than the renders before; the tables are kept per device, Context::derived) and
// whose programs are built.
double table_seconds_per_material(const FrameScene& frame, const FrameHooks& hooks) {
    const TimedFrame tables = timed_frame(
        frame, {"rc", {{"--ic-rays", "16"}, {"--rc-max-error", "0.0999"}}}, 8, 1, hooks);
    const nlohmann::json& rc = tables.result.stats.at("radiance_cache");
    const size_t glossy = glossy_table_count(rc.at("materials"));
    return rc.at("seconds").value("tables", 0.0) / static_cast<double>(std::max<size_t>(glossy, 1));
}

DeviceThroughput measure_throughput(const FrameScene& frame, const FrameHooks& hooks) {
    DeviceThroughput t;
    timed_frame(frame, {"pt", {}}, 8, 1, hooks);  // its programs built before the timing
    const TimedFrame pt = timed_frame(frame, {"pt", {}}, kSide, kPathTracerSpp, hooks);
    t.pt_seconds_per_ray = pt.seconds / static_cast<double>(std::max<uint64_t>(pt.result.rays, 1));
    for (const char* method : kCachingMethods) {
        const int rays[2] = {kFewRays, static_cast<int>(declared_default(method, "--ic-rays"))};
        timed_frame(frame, {method, {{"--ic-rays", std::to_string(rays[0])}}}, 8, 1,
                    hooks);  // its programs built (or loaded) before the timing
        if (std::string(method) == "rc") {
            t.table_seconds_per_material = table_seconds_per_material(frame, hooks);
        }
        CacheRayCost& cost = t.cache_seconds_per_ray[method];
        for (int i = 0; i < 2; ++i) {
            // The camera samples' figure from the first (its cache is the smaller share).
            const int spp = i == 0 ? kCameraSpp : 1;
            const TimedFrame cached = timed_frame(
                frame, {method, {{"--ic-rays", std::to_string(rays[i])}}}, kSide, spp, hooks);
            const uint64_t cache_rays =
                std::min(cache_rays_of(cached.result.stats), cached.result.rays);
            const double cache_seconds = std::min(cached.result.cache_seconds, cached.seconds);
            cost.rays[i] = rays[i];
            cost.seconds_per_ray[i] =
                cache_seconds / static_cast<double>(std::max<uint64_t>(cache_rays, 1));
            if (i == 0) {
                t.camera_seconds_per_ray[method] =
                    (cached.seconds - cache_seconds) /
                    static_cast<double>(std::max<uint64_t>(cached.result.rays - cache_rays, 1));
            }
        }
    }
    return t;
}

}  // namespace

double CacheRayCost::at(int rays_per_record) const {
    // s(R) = a + b / R through (R0, s0) and (R1, s1); b >= 0 (more rays never cost more per
    // ray than fewer), a >= 0.
    const double inverse[2] = {1.0 / rays[0], 1.0 / rays[1]};
    const double b =
        std::max(0.0, (seconds_per_ray[0] - seconds_per_ray[1]) / (inverse[0] - inverse[1]));
    const double a = std::max(0.0, seconds_per_ray[1] - b * inverse[1]);
    const double s = a + b / std::max(rays_per_record, 1);
    return s > 0.0 ? s : std::max(seconds_per_ray[0], seconds_per_ray[1]);
}

double DeviceThroughput::cache_of(const std::string& method, int rays_per_record) const {
    const auto found = cache_seconds_per_ray.find(method);
    return (found != cache_seconds_per_ray.end() ? found->second : cache_seconds_per_ray.at("ic"))
        .at(rays_per_record);
}

double DeviceThroughput::camera_of(const std::string& method) const {
    const auto found = camera_seconds_per_ray.find(method);
    return found != camera_seconds_per_ray.end() ? found->second : camera_seconds_per_ray.at("ic");
}

DeviceThroughput device_throughput(Context& context, const FrameHooks& hooks) {
    DeviceThroughput cached;
    cached.file = throughput_file(context);
    if (!cached.file.empty() && read_throughput(cached.file, &cached)) {
        return cached;
    }
    log_note("auto: measuring this device's throughput once (some seconds; cached in " +
             (cached.file.empty() ? std::string("no cache directory") : cached.file.string()) +
             ")");
    MemoryFiles files;
    files.add("throughput/scene.json", kThroughputScene);
    Scene scene = load_scene("throughput/scene.json", files);
    const Bvh bvh = build_bvh(scene.mesh, context.bvh_layout());
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    FrameHooks own = hooks;
    own.visit_frame = nullptr;
    DeviceThroughput measured =
        measure_throughput({context, scene, device_bvh, device_scene, 0}, own);
    measured.file = cached.file;
    measured.measured_now = true;
    return measured.file.empty() ? measured : cache_throughput(measured, context);
}

}  // namespace rc
