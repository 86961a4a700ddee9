// The model `--method auto` plans with (docs/auto.md): how a caching method's work grows from its
// pilot to the full render, and its error against the path tracer's noise. The constants are
// data, auto_model.json beside this file, embedded at build and refitted from measurements by
// tools/auto_model.py.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rc {

// Cache work (rays) at the full image from the pilot's: W = scale W_p (P / P_p)^gamma
// (R / R_p)^rho (a_p / a)^alpha s^sigma, P pixels, R hemisphere rays per record (--ic-rays), a
// the accuracy, s the camera samples per pixel (records are placed at the camera samples; the
// pilot takes one).
struct AutoCostModel {
    double scale = 1.0;
    double gamma = 0.3;
    double rho = 1.0;
    double alpha = 1.0;
    double sigma = 0.0;
};

// relMSE of s camera samples over the cache: (delta v_dir + phi v_ind) / s + beta a^2 f^2 +
// kappa v_ind / R, with v_dir and v_ind the per-sample relMSE of the direct and the indirect light
// (the path tracer's v_pt = v_dir + v_ind) and f the indirect share of the image, from the pilot.
struct AutoErrorModel {
    double delta = 1.0;  // the share of the path tracer's direct noise the camera samples keep
    double phi = 0.1;    // the share of the indirect noise the camera samples keep
    double beta = 0.05;  // interpolation error per a^2 f^2
    double kappa = 1.0;  // record noise per v_ind / R
    // The law's typical factor of error on the runs it was fitted to (exp of the root mean square
    // of log(predicted / measured)): knobs other than the method's defaults are chosen only when
    // predicted better than the defaults by more than this (the defaults' error is measured where
    // the law's is extrapolated).
    double spread = 1.0;
};

struct AutoModel {
    int pilot_divisor = 8;            // the pilot image is 1/divisor of the width and the height
    int pilot_min_side = 32;          // ... and at least this many pixels on its shorter side
    int pilot_pt_spp = 2;             // samples of each of the path tracer's two pilot images
    int pilot_rays_divisor = 8;       // the cache pilot's --ic-rays: the default's 1/divisor
    double max_pilot_fraction = 0.1;  // the most of --time the pilot may take
    std::vector<double> accuracies;   // --accuracy values the plan chooses from
    std::vector<int> ic_rays;         // --ic-rays values the plan chooses from
    std::map<std::string, AutoCostModel> cost;  // by caching method: ic, rc, sdrc
    std::map<std::string, AutoErrorModel> error;
    double rc_max_fallback = 0.5;  // rc serves lobes its tables leave at most this to Monte Carlo
    double sdrc_max_exponent = 1000;    // sdrc serves lobes up to this Phong exponent
    double temporal_max_motion = 0.01;  // per frame, over the scene's diagonal
    std::string fitted;                 // how the constants were obtained

    const AutoCostModel& cost_of(const std::string& method) const;
    const AutoErrorModel& error_of(const std::string& method) const;
};

// The model in `json` (auto_model.json's form); Error naming the first missing or bad key.
AutoModel parse_auto_model(const nlohmann::json& json);

// The embedded model (parsed once).
const AutoModel& auto_model();

}  // namespace rc
