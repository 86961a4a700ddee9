#include "app/ray_bench.h"

#include <algorithm>
#include <chrono>

namespace rc {
namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

}  // namespace

RayBench::RayBench(Context& context, const Scene& scene, unsigned embree_threads, int repeats)
    : context_(context),
      bvh_(build_bvh(scene.mesh, context.bvh_layout())),
      device_bvh_(context, bvh_),
      tracer_(context, device_bvh_),
      embree_(scene.mesh),
      threads_(embree_threads),
      repeats_(repeats) {}

std::vector<RayCaseResult> RayBench::run(const std::vector<shared::Ray>& coherent,
                                         const std::vector<shared::Ray>& incoherent) {
    std::vector<RayCaseResult> results;
    for (const auto& [name, rays] :
         {std::pair{"coherent", &coherent}, std::pair{"incoherent", &incoherent}}) {
        results.push_back(closest_case(std::string(name) + "_closest", *rays));
        results.push_back(any_case(std::string(name) + "_any", *rays));
    }
    return results;
}

double RayBench::device_seconds(const std::string& kernel, const std::function<void()>& launch) {
    launch();  // warm-up: the first launch may generate code for the work-group size
    std::vector<double> times;
    for (int r = 0; r < repeats_; ++r) {
        const double before = context_.kernel_times().at(kernel).seconds;
        launch();
        times.push_back(context_.kernel_times().at(kernel).seconds - before);
    }
    return median(times);
}

double RayBench::embree_seconds(const std::function<void()>& trace) {
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

RayCaseResult RayBench::finish(const std::string& name, size_t rays, double device_s,
                               double embree_s, size_t agreeing) {
    RayCaseResult result;
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

RayCaseResult RayBench::closest_case(const std::string& name,
                                     const std::vector<shared::Ray>& rays) {
    const Buffer<shared::Ray> ray_buffer(context_, rays, "bench_rays");
    Buffer<shared::Hit> hit_buffer(context_, rays.size(), "bench_hits");
    const double device_s =
        device_seconds("trace_closest", [&] { tracer_.trace_closest(ray_buffer, hit_buffer); });
    std::vector<shared::Hit> embree_hits;
    const double embree_s = embree_seconds([&] { embree_.intersect(rays, embree_hits, threads_); });
    const std::vector<shared::Hit> device_hits = hit_buffer.download();
    size_t agreeing = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        agreeing += same_closest_hit(device_hits[i], embree_hits[i]) ? 1 : 0;
    }
    return finish(name, rays.size(), device_s, embree_s, agreeing);
}

RayCaseResult RayBench::any_case(const std::string& name, const std::vector<shared::Ray>& rays) {
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

}  // namespace rc
