#include "app/render_stats.h"

#include <algorithm>

#include "util/host_memory.h"
#include "util/log.h"

namespace rc {

void RenderTotals::add_frame(int frame, const std::filesystem::path& output,
                             const FrameResult& result, Context& context) {
    nlohmann::json entry = result.stats;
    entry["frame"] = frame;
    entry["output"] = output.string();
    // Memory of the frame: now, and the most since the previous frame.
    const HostMemory host = host_memory();
    const DeviceMemory& device = context.device_memory();
    nlohmann::json need_parts = nlohmann::json::object();
    for (const DeviceMemoryNeed::Part& part : frame_need_.parts) {
        need_parts[part.name] = part.bytes;
    }
    entry["memory"] = {{"host_resident_bytes", host.resident},
                       {"host_peak_resident_bytes", host.peak_resident},
                       {"device_bytes", device.in_use},
                       {"device_peak_bytes", device.peak},
                       {"device_need_bytes", frame_need_.total()},
                       {"device_need_parts", need_parts},
                       {"device_need_excludes", frame_need_.excludes}};
    host_peak_ = std::max(host_peak_, host.peak_resident);
    device_peak_ = std::max(device_peak_, device.peak);
    device_need_ = std::max(device_need_, frame_need_.total());
    reset_host_memory_peak();
    context.reset_peak_memory();
    frames_.push_back(entry);
    rays_ += result.rays;
    nonfinite_ += result.nonfinite_samples;
    if (first_nonfinite_pixel_ < 0) {
        first_nonfinite_pixel_ = result.first_nonfinite_pixel;
    }
    spp_ = result.spp;
    width_ = result.image.width;
    height_ = result.image.height;
    if (result.nonfinite_samples > 0) {
        const int64_t pixel = result.first_nonfinite_pixel;
        log_warning(std::to_string(result.nonfinite_samples) +
                    " samples were NaN or infinite and were dropped (first at pixel " +
                    std::to_string(pixel % width_) + ", " + std::to_string(pixel / width_) + ")");
    }
}

namespace {

nlohmann::json kernel_times_json(const Context& context) {
    nlohmann::json kernels = nlohmann::json::object();
    for (const auto& [name, time] : context.kernel_times()) {
        kernels[name] = {
            {"seconds", time.seconds}, {"launches", time.launches}, {"items", time.items}};
    }
    return kernels;
}

nlohmann::json program_builds_json(const Context& context) {
    nlohmann::json builds = nlohmann::json::array();
    for (const ProgramBuildReport& build : context.program_builds()) {
        builds.push_back({{"program", build.entry},
                          {"options", build.options},
                          {"seconds", build.seconds},
                          {"from_cache", build.from_cache}});
    }
    return builds;
}

nlohmann::json prebuild_requests_json(const Context& context) {
    nlohmann::json requests = nlohmann::json::array();
    for (const ProgramRequest& request : context.prebuild_requests()) {
        requests.push_back({{"program", request.entry}, {"options", request.options}});
    }
    return requests;
}

}  // namespace

nlohmann::json RenderTotals::json(const RenderSettings& settings, const Scene& scene,
                                  const Context& context, const Bvh& bvh,
                                  double total_seconds) const {
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
    stats["dropped_repeated_triangles"] = scene.dropped_repeated;
    stats["resolution"] = {width_, height_};
    stats["spp"] = spp_;
    stats["filter"] = {{"type", pixel_filter_name(scene.camera.filter.type)},
                       {"radius", scene.camera.filter.radius}};
    stats["sampler"] = pixel_sampler_name(scene.camera.sampler);
    stats["seed"] = settings.seed;
    stats["max_depth"] = settings.max_depth;
    stats["frames"] = frames_;
    stats["seconds"] = seconds_;
    stats["seconds"]["total"] = total_seconds;
    stats["kernels"] = kernel_times_json(context);
    stats["rays"] = rays_;
    stats["mrays_per_second"] = kernel_seconds > 0.0 ? rays_ / kernel_seconds * 1e-6 : 0.0;
    stats["nonfinite_samples"] = nonfinite_;
    stats["first_nonfinite_pixel"] = first_nonfinite_pixel_;
    stats["program_builds"] = program_builds_json(context);
    stats["prebuilt_programs"] = prebuild_requests_json(context);
    stats["memory"] = {{"host_peak_resident_bytes", host_peak_},
                       {"device_peak_bytes", device_peak_},
                       {"device_need_bytes", device_need_},
                       {"device_global_bytes", context.device().global_memory}};
    stats["bvh"] = {{"layout", bvh_layout_name(bvh.layout)},
                    {"nodes", bvh.node_count()},
                    {"leaves", bvh.leaf_count},
                    {"depth", bvh.depth},
                    {"bytes", bvh.device_bytes()}};
    return stats;
}

}  // namespace rc
