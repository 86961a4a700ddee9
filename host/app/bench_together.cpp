#include "app/bench_together.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "device/device_features.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/frame_scene.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/path_tracer/path_tracer.h"
#include "scene/device_scene.h"
#include "util/error.h"
#include "util/timing.h"

namespace rc {
namespace {

// One device's copy of the scene: its context, BVH and scene buffers.
struct DeviceFrame {
    std::unique_ptr<Context> context;
    std::unique_ptr<DeviceBvh> bvh;
    std::unique_ptr<DeviceScene> device_scene;
};

// A whole render timed on the wall clock; `run` renders `frame` (alone or with its peers) and
// returns the work it did (camera samples, photons).
struct TogetherCase {
    std::string key;
    std::string label;
    std::function<double(const FrameScene& frame, bool warm_up)> run;
};

double median(std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

std::vector<TogetherCase> together_cases(const Scene& scene, const TogetherSettings& settings) {
    return {
        {"path_samples_per_second", "pt render, camera samples/s (M)",
         [&scene, settings](const FrameScene& frame, bool warm_up) {
             PathTracerOptions pt;
             pt.width = warm_up ? 16 : settings.width;
             pt.height = warm_up ? 16 : settings.height;
             pt.spp = warm_up ? 1 : settings.spp;
             pt.max_depth = scene.render.max_depth;
             pt.rr_depth = scene.render.rr_depth;
             PathTracer(frame).render(pt);
             return static_cast<double>(pt.width) * pt.height * pt.spp;
         }},
        {"ic_samples_per_second", "ic render (1 spp), camera samples/s (M)",
         [&scene, settings](const FrameScene& frame, bool warm_up) {
             PipelineSettings ic;
             ic.width = warm_up ? 16 : settings.width;
             ic.height = warm_up ? 16 : settings.height;
             ic.spp = 1;
             ic.max_depth = scene.render.max_depth;
             ic.rr_depth = scene.render.rr_depth;
             ic.records_overlay = false;
             CachePipeline(frame).render(ic);
             return static_cast<double>(ic.width) * ic.height;
         }},
        {"photons_per_second", "grid build, photons/s (M)",
         [&scene, settings](const FrameScene& frame, bool warm_up) {
             IvgOptions ivg;
             ivg.max_depth = scene.render.max_depth;
             ivg.rr_depth = scene.render.rr_depth;
             ivg.photons = warm_up ? 1024 : settings.photons;
             IvgStats stats;
             IrradianceVectorGrid(frame).build(ivg, &stats);
             return static_cast<double>(stats.photons);
         }},
    };
}

// Throughput (work per wall-clock second, in millions) of one run of `c` on `frame`.
double timed_run(const TogetherCase& c, const FrameScene& frame) {
    frame.context.finish();
    const auto start = SteadyClock::now();
    const double work = c.run(frame, false);
    frame.context.finish();
    return work / seconds_since(start) * 1e-6;
}

}  // namespace

double TogetherFigure::sum_alone() const {
    double sum = 0.0;
    for (double value : alone) {
        sum += value;
    }
    return sum;
}

double TogetherFigure::best_alone() const { return *std::max_element(alone.begin(), alone.end()); }

std::vector<TogetherFigure> bench_devices_together(const std::vector<DeviceInfo>& devices,
                                                   ContextOptions options, const Scene& scene,
                                                   const TogetherSettings& settings) {
    if (devices.size() < 2) {
        throw Error("bench all: the devices-together figures need at least two devices",
                    kExitUsage);
    }
    std::vector<DeviceFrame> copies;
    std::vector<FrameScene> alone;
    for (const DeviceInfo& device : devices) {
        options.device_spec = device.spec();
        DeviceFrame copy;
        copy.context = std::make_unique<Context>(options);
        refuse_loop_capped_device(*copy.context);
        const Bvh bvh = build_bvh(scene.mesh, copy.context->bvh_layout());
        copy.bvh = std::make_unique<DeviceBvh>(*copy.context, bvh);
        copy.device_scene = std::make_unique<DeviceScene>(*copy.context, scene);
        copies.push_back(std::move(copy));
    }
    for (const DeviceFrame& copy : copies) {
        alone.push_back({*copy.context, scene, *copy.bvh, *copy.device_scene, 0, nullptr});
    }
    const std::vector<FrameScene> peers(alone.begin() + 1, alone.end());
    const FrameScene together{alone[0].context,      scene, alone[0].bvh,
                              alone[0].device_scene, 0,     &peers};

    std::vector<TogetherFigure> figures;
    for (const TogetherCase& c : together_cases(scene, settings)) {
        for (const FrameScene& frame : alone) {
            c.run(frame, true);  // builds and warms this device's kernels
        }
        std::vector<std::vector<double>> rounds(devices.size() + 1);
        for (int r = 0; r < settings.repeats; ++r) {  // interleaved: every run meets the same load
            for (size_t d = 0; d < alone.size(); ++d) {
                rounds[d].push_back(timed_run(c, alone[d]));
            }
            rounds.back().push_back(timed_run(c, together));
        }
        TogetherFigure figure{c.key, c.label, {}, median(rounds.back())};
        for (size_t d = 0; d < alone.size(); ++d) {
            figure.alone.push_back(median(rounds[d]));
        }
        figures.push_back(figure);
    }
    return figures;
}

void print_together(const std::vector<DeviceInfo>& devices,
                    const std::vector<TogetherFigure>& figures) {
    std::printf("\ndevices together (whole renders, wall clock, median of the rounds)\n%-36s",
                "figure");
    for (const DeviceInfo& device : devices) {
        std::printf(" %10s alone", device.spec().c_str());
    }
    std::printf(" %12s %12s %12s %13s\n", "sum alone", "together", "together/sum", "together/best");
    for (const TogetherFigure& f : figures) {
        std::printf("%-36s", f.label.c_str());
        for (double value : f.alone) {
            std::printf(" %16.3f", value);
        }
        std::printf(" %12.3f %12.3f %12.3f %13.3f\n", f.sum_alone(), f.together,
                    f.together / f.sum_alone(), f.together / f.best_alone());
    }
}

nlohmann::json together_json(const std::vector<DeviceInfo>& devices,
                             const std::vector<TogetherFigure>& figures) {
    nlohmann::json report;
    report["devices"] = nlohmann::json::array();
    for (const DeviceInfo& device : devices) {
        report["devices"].push_back(device.spec());
    }
    for (const TogetherFigure& f : figures) {
        report[f.key] = {{"alone", f.alone},
                         {"sum_alone", f.sum_alone()},
                         {"together", f.together},
                         {"together_over_sum", f.together / f.sum_alone()},
                         {"together_over_best", f.together / f.best_alone()}};
    }
    return report;
}

}  // namespace rc
