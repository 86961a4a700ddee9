// The plan of `--method auto` (docs/auto.md, "The plan"): which method renders, with which
// knobs and samples, chosen from the pilot's figures by the model, and the line and statistics
// that report it.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "methods/auto/auto_materials.h"
#include "methods/auto/auto_model.h"
#include "methods/auto/auto_pilot.h"
#include "methods/auto/auto_runs.h"
#include "methods/auto/auto_throughput.h"

namespace rc {

// What the plan is chosen from.
struct PlanInputs {
    double budget = 0.0;     // --time (seconds per frame); 0: none
    int spp = 16;            // the render's samples per pixel
    bool spp_fixed = false;  // --spp given: the samples are the user's
    double pixels = 0.0;     // of the render's image
    int frames = 1;
    double motion = 0.0;  // clip_motion
    const AutoModel* model = nullptr;
    const DeviceThroughput* throughput = nullptr;
    NoisePilot noise;
    std::optional<CachePilot> cache;  // none: nothing to cache
    std::vector<MaterialChoice> materials;
    MethodRun cache_run;         // the caching method that serves the materials (without knobs)
    double pilot_seconds = 0.0;  // the pilot's work at the device's throughput
    // Radiance caching's BRDF tables, built by the pilot and kept for the render (their time is
    // the plan's, not the pilot's share).
    double tables_seconds = 0.0;
};

struct AutoPlan {
    MethodRun run;  // what renders each frame
    std::vector<MaterialChoice> materials;
    int spp = 1;
    double accuracy = 0.0;  // 0: the path tracer
    int ic_rays = 0;
    bool temporal = false;
    double pilot_seconds = 0.0;
    double predicted_seconds = 0.0;        // the frame after the pilot
    double predicted_cache_seconds = 0.0;  // of which the caches
    double predicted_relmse = 0.0;
    // What the plan is chosen by: the predicted relMSE, times the error law's spread where the
    // knobs are not the method's defaults (AutoErrorModel::spread); the path tracer's is its own.
    double trusted_relmse = 0.0;
    bool default_knobs = false;      // the caching method's --accuracy and --ic-rays defaults
    double pt_relmse = 0.0;          // the path tracer's in the same time
    double cache_min_seconds = 0.0;  // the cheapest cache the plan could have built
    std::string why;                 // why the path tracer renders, when it does

    bool caches() const { return run.method != "pt"; }
    // "auto: ic for 5 diffuse materials, sdrc for 'kettle', pt for 'mirror'; accuracy 0.35,
    // 512 rays, 24 spp; predicted 29.6 s, relMSE 1.2e-04 (pt 9.1e-04); pilot 0.4 s"
    std::string line() const;
    nlohmann::json json(const PlanInputs& inputs) const;
};

// The plan with the lowest trusted relMSE (AutoPlan::trusted_relmse) within the budget (without
// one: the materials' methods at their default knobs and the render's samples). Error (exit status
// 2) when the budget does not hold the pilot's share (model.max_pilot_fraction).
AutoPlan choose_plan(const PlanInputs& inputs);

// The caching method that serves `choices` (one per material of `materials`): ic when no glossy
// lobe is cached, rc or sdrc when one of them serves every glossy lobe, else ic with the
// per-material --glossy list (methods/caching/glossy_spec.h).
MethodRun caching_run(const std::vector<MaterialChoice>& choices,
                      const std::vector<Material>& materials);

// The model constants' name for a caching run ("ic", "rc" or "sdrc").
std::string model_key(const std::vector<MaterialChoice>& materials);

}  // namespace rc
