// This device's seconds per ray for the work `--method auto` plans (docs/auto.md, "Seconds from
// work"): the path tracer's camera samples, and each caching method's record rays and camera-sample
// rays. Measured once per device on a small built-in scene and cached beside the kernel binaries
// (the file names the device and its driver), so that every plan on the device converts work to
// seconds with the same figures, whatever the machine's load when it plans.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "methods/method.h"

namespace rc {

// A caching method's seconds per record ray, measured at two --ic-rays: a record's fixed work
// (placement, its launch, its insertion) is shared by its rays, so a ray costs s(R) = a + b / R
// with R rays per record (at 128 rays a record ray took 1.7 times its time at 1024 here).
struct CacheRayCost {
    int rays[2] = {0, 0};                  // the --ic-rays measured, rays[0] < rays[1]
    double seconds_per_ray[2] = {0., 0.};  // measured at each
    // s(R) through the two measurements (b >= 0, a >= 0).
    double at(int rays_per_record) const;
};

struct DeviceThroughput {
    double pt_seconds_per_ray = 0.0;
    std::map<std::string, CacheRayCost> cache_seconds_per_ray;  // by method: ic, rc, sdrc
    std::map<std::string, double> camera_seconds_per_ray;       // by method: ic, rc, sdrc
    // Radiance caching's BRDF tables (built once per render and device, whatever the image):
    // seconds per material with a glossy lobe.
    double table_seconds_per_material = 0.0;
    std::filesystem::path file;  // where it is cached (empty: no cache directory)
    bool measured_now = false;   // this call measured it (no cached figures were found)

    // Seconds per record ray of `method` at `rays_per_record` (--ic-rays).
    double cache_of(const std::string& method, int rays_per_record) const;
    double camera_of(const std::string& method) const;
};

// The cached figures of `context`'s device, or measured now (and cached, unless another process
// cached its own first: then those). Measuring renders pt, ic, rc and sdrc on the built-in scene
// (about 30 s on 2 CPU cores; each caching method at two --ic-rays), after a first tiny render of
// each so compilation is not counted.
DeviceThroughput device_throughput(Context& context, const FrameHooks& hooks);

}  // namespace rc
