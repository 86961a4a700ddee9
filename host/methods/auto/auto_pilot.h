// The pilot of `--method auto` (docs/auto.md, "The pilot"): small renders of the scene on this
// device. Its figures are work counts and image statistics, never seconds, so the plan made from
// them does not depend on the machine's load; seconds come from the device's throughput
// (auto_throughput.h).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "methods/auto/auto_model.h"
#include "methods/auto/auto_runs.h"
#include "methods/method.h"

namespace rc {

struct PilotSize {
    int width = 0;
    int height = 0;
    double pixels() const { return static_cast<double>(width) * height; }
};

// The render's image size: the settings', else the scene camera's.
int render_width(const MethodSettings& settings, const FrameScene& frame);
int render_height(const MethodSettings& settings, const FrameScene& frame);

// The pilot image of a width x height render: 1/divisor of each side, the shorter side at least
// min_side (and never above the render's), the aspect kept.
PilotSize pilot_size(const AutoModel& model, int width, int height);

// The path tracer's noise at the pilot size: two images of pt_spp samples with different seeds,
// of all the light and of the direct light alone (max_depth 1).
struct NoisePilot {
    PilotSize size;
    // relMSE of one camera sample (the mean over pixels and channels of its variance over
    // (mean^2 + 0.01), as `radcache compare` weighs errors): all the light, and the direct light.
    double v_pt = 0.0;
    double v_direct = 0.0;
    double indirect_fraction = 0.0;  // f: the share of the image's light that is indirect
    double rays_per_sample = 0.0;    // the path tracer's rays per camera sample
    uint64_t rays = 0;               // what the noise pilot traced
    double v_indirect() const { return v_pt > v_direct ? v_pt - v_direct : 0.0; }
};

NoisePilot noise_pilot(const FrameScene& frame, const MethodSettings& settings,
                       const AutoModel& model, const FrameHooks& hooks);

// A caching method at the pilot size with 1/rays_divisor of its hemisphere rays and one camera
// sample per pixel: the work of its caches and of its camera samples.
struct CachePilot {
    MethodRun run;  // as it ran (its --ic-rays the pilot's)
    PilotSize size;
    int ic_rays = 0;
    double accuracy = 0.0;
    uint64_t cache_rays = 0;  // every cache's record rays
    double camera_rays_per_sample = 0.0;
    uint64_t rays = 0;
    nlohmann::json stats;  // the frame's statistics (radiance caching's materials among them)
};

// `run` at the pilot size; its accuracy and rays per record the defaults' unless `run` gives them.
CachePilot cache_pilot(const FrameScene& frame, const MethodSettings& settings,
                       const AutoModel& model, MethodRun run, const FrameHooks& hooks);

// What radiance caching's BRDF tables make of the scene's materials (the adaptive order, TVCG
// 2005 §4.1): its statistics' "materials" ({name, kind, order, fallback_fraction}), from a render
// of 8 x 8 pixels with 16 rays per record (the tables do not depend on the image).
struct TablePilot {
    nlohmann::json materials = nlohmann::json::array();
    uint64_t rays = 0;
    size_t glossy_materials = 0;  // the tables built (kind glossy or fallback)
};

// The materials with a table (kind glossy or fallback) in radiance caching's statistics'
// "materials".
size_t glossy_table_count(const nlohmann::json& materials);

// The tables pilot's rays per record.
constexpr int kTableRays = 16;

TablePilot brdf_table_pilot(const FrameScene& frame, const MethodSettings& settings,
                            const FrameHooks& hooks);

// The record rays of every cache in a caching method's frame statistics.
uint64_t cache_rays_of(const nlohmann::json& stats);

}  // namespace rc
