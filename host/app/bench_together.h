// `radcache bench all` with several devices: whole renders that split their work across
// devices (the path tracer's pixel chunks, irradiance caching's record batches and final pass at
// its defaults and one camera sample per pixel, the grid's photon batches) timed on the wall clock
// on each device alone and on all of them together, side by side in one run, so the together
// throughput can be read against the sum of the single-device ones.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "device/context.h"
#include "device/device_list.h"
#include "scene/scene.h"

namespace rc {

struct TogetherFigure {
    std::string key;            // JSON name: "path_samples_per_second"
    std::string label;          // table row
    std::vector<double> alone;  // per device, the median round's throughput
    double together = 0.0;      // all devices in one render, the median round's

    double sum_alone() const;
    double best_alone() const;
};

struct TogetherSettings {
    int width = 512;
    int height = 512;
    int spp = 4;
    uint64_t photons = 1 << 18;
    int repeats = 3;  // rounds of every case (alone on each device, then together); medians kept
};

// Opens one context per device (at least two), uploads the scene to each, warms every kernel up,
// then runs `repeats` rounds of each case: on every device alone, then on all together.
std::vector<TogetherFigure> bench_devices_together(const std::vector<DeviceInfo>& devices,
                                                   ContextOptions options, const Scene& scene,
                                                   const TogetherSettings& settings);

// The table: one row per figure, a column per device alone, their sum, together, together/sum
// (the figure for devices that share no hardware: a CPU and a GPU, two GPUs) and together/best
// (the figure for devices that share one pool of cores, as PoCL's pthread devices in one process
// do: there the split can at best match one device alone).
void print_together(const std::vector<DeviceInfo>& devices,
                    const std::vector<TogetherFigure>& figures);

nlohmann::json together_json(const std::vector<DeviceInfo>& devices,
                             const std::vector<TogetherFigure>& figures);

}  // namespace rc
