// The traversal measurement shared by `radcache bench rays` and `radcache bench pt`: device
// throughput against Embree's rtcIntersect1 / rtcOccluded1 on the very same rays and triangles,
// side by side in one run.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "bvh/embree_scene.h"
#include "device/context.h"
#include "scene/scene.h"

namespace rc {

struct RayCaseResult {
    std::string name;  // coherent_closest, coherent_any, incoherent_closest, incoherent_any
    size_t rays = 0;
    double device_mrays = 0.0;
    double embree_mrays = 0.0;
    double ratio_per_thread = 0.0;  // (device per compute unit) / (Embree per thread)
    double agreement = 0.0;         // fraction of rays with the same answer
};

class RayBench {
   public:
    RayBench(Context& context, const Scene& scene, unsigned embree_threads, int repeats);

    DeviceTracer& tracer() { return tracer_; }
    const Bvh& bvh() const { return bvh_; }
    const DeviceBvh& device_bvh() const { return device_bvh_; }

    // The four cases on camera rays (coherent) and their diffuse bounces (incoherent).
    std::vector<RayCaseResult> run(const std::vector<shared::Ray>& coherent,
                                   const std::vector<shared::Ray>& incoherent);

   private:
    double device_seconds(const std::string& kernel, const std::function<void()>& launch);
    double embree_seconds(const std::function<void()>& trace);
    RayCaseResult finish(const std::string& name, size_t rays, double device_s, double embree_s,
                         size_t agreeing);
    RayCaseResult closest_case(const std::string& name, const std::vector<shared::Ray>& rays);
    RayCaseResult any_case(const std::string& name, const std::vector<shared::Ray>& rays);

    Context& context_;
    Bvh bvh_;
    DeviceBvh device_bvh_;
    DeviceTracer tracer_;
    EmbreeScene embree_;
    unsigned threads_;
    int repeats_;
};

}  // namespace rc
