#include "methods/auto/auto_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "methods/caching/glossy_spec.h"
#include "util/error.h"

namespace rc {
namespace {

constexpr int kMaxSpp = 1 << 20;

std::string number_text(double value, const char* format = "%g") {
    char text[32];
    std::snprintf(text, sizeof(text), format, value);
    return text;
}

// The seconds of the caches and of one camera sample per pixel over them, at knobs (a, R).
struct CacheCost {
    double cache_seconds = 0.0;
    double sample_seconds = 0.0;
};

CacheCost cache_cost(const PlanInputs& in, const std::string& key, double accuracy, int rays,
                     int spp) {
    const AutoCostModel& c = in.model->cost_of(key);
    const CachePilot& pilot = *in.cache;
    const double work = c.scale * static_cast<double>(pilot.cache_rays) *
                        std::pow(in.pixels / pilot.size.pixels(), c.gamma) *
                        std::pow(static_cast<double>(rays) / pilot.ic_rays, c.rho) *
                        std::pow(pilot.accuracy / accuracy, c.alpha) *
                        std::pow(static_cast<double>(spp), c.sigma);
    CacheCost cost;
    cost.cache_seconds = work * in.throughput->cache_of(key, rays);
    cost.sample_seconds = in.pixels * pilot.camera_rays_per_sample * in.throughput->camera_of(key);
    return cost;
}

// Equation of docs/auto.md: (delta v_dir + phi v_ind) / s + beta a^2 f^2 + kappa v_ind / R.
double cache_relmse(const PlanInputs& in, const std::string& key, double accuracy, int rays,
                    int spp) {
    const AutoErrorModel& e = in.model->error_of(key);
    const NoisePilot& n = in.noise;
    const double f = n.indirect_fraction;
    return (e.delta * n.v_direct + e.phi * n.v_indirect()) / spp +
           e.beta * accuracy * accuracy * f * f + e.kappa * n.v_indirect() / rays;
}

int samples_in(double seconds, double per_sample) {
    if (per_sample <= 0.0) {
        return kMaxSpp;
    }
    return static_cast<int>(std::clamp(std::floor(seconds / per_sample), 0.0, double{kMaxSpp}));
}

// The most samples per pixel whose cache and samples fit in `available` (0: not one).
int samples_within(const PlanInputs& in, const std::string& key, double accuracy, int rays,
                   double available) {
    const auto fits = [&](int spp) {
        const CacheCost cost = cache_cost(in, key, accuracy, rays, spp);
        return cost.cache_seconds + spp * cost.sample_seconds <= available;
    };
    if (!fits(1)) {
        return 0;
    }
    int low = 1;  // fits
    int high = kMaxSpp;
    if (fits(high)) {
        return high;
    }
    while (high - low > 1) {  // the cost grows with the samples: bisect
        const int middle = low + (high - low) / 2;
        (fits(middle) ? low : high) = middle;
    }
    return low;
}

AutoPlan path_tracer_plan(const PlanInputs& in, double available) {
    AutoPlan plan;
    plan.run = {"pt", {}};
    const double per_sample =
        in.pixels * in.noise.rays_per_sample * in.throughput->pt_seconds_per_ray;
    plan.spp =
        in.spp_fixed || in.budget <= 0.0 ? in.spp : std::max(1, samples_in(available, per_sample));
    plan.predicted_seconds = plan.spp * per_sample;
    plan.predicted_relmse = in.noise.v_pt / plan.spp;
    plan.trusted_relmse = plan.predicted_relmse;
    plan.pt_relmse = plan.predicted_relmse;
    return plan;
}

AutoPlan cache_plan(const PlanInputs& in, double accuracy, int rays, int spp) {
    const std::string key = model_key(in.materials);
    const CacheCost cost = cache_cost(in, key, accuracy, rays, spp);
    AutoPlan plan;
    plan.default_knobs =
        accuracy == declared_default(in.cache_run.method, "--accuracy") &&
        rays == static_cast<int>(declared_default(in.cache_run.method, "--ic-rays"));
    plan.run = in.cache_run;
    plan.run.options.push_back({"--accuracy", number_text(accuracy)});
    plan.run.options.push_back({"--ic-rays", std::to_string(rays)});
    plan.accuracy = accuracy;
    plan.ic_rays = rays;
    plan.spp = spp;
    plan.predicted_cache_seconds = cost.cache_seconds;
    plan.predicted_seconds = cost.cache_seconds + spp * cost.sample_seconds;
    plan.predicted_relmse = cache_relmse(in, key, accuracy, rays, spp);
    // Knobs other than the defaults are trusted only beyond the law's spread: their error is
    // extrapolated, the defaults' measured (AutoErrorModel::spread).
    plan.trusted_relmse =
        plan.predicted_relmse * (plan.default_knobs ? 1.0 : in.model->error_of(key).spread);
    return plan;
}

// The knobs searched: the model's grid and the caching method's defaults.
std::vector<std::pair<double, int>> searched_knobs(const PlanInputs& in) {
    std::vector<std::pair<double, int>> knobs = {
        {declared_default(in.cache_run.method, "--accuracy"),
         static_cast<int>(declared_default(in.cache_run.method, "--ic-rays"))}};
    for (double accuracy : in.model->accuracies) {
        for (int rays : in.model->ic_rays) {
            if (std::pair(accuracy, rays) != knobs.front()) {
                knobs.emplace_back(accuracy, rays);
            }
        }
    }
    return knobs;
}

// The knobs with the lowest trusted relMSE (AutoPlan::trusted_relmse) whose cache and samples fit
// in `available`; none when no cache fits with one sample per pixel (cache_min_seconds: the
// cheapest one's seconds).
std::optional<AutoPlan> best_cache_plan(const PlanInputs& in, double available,
                                        double* cache_min_seconds) {
    std::optional<AutoPlan> best;
    *cache_min_seconds = std::numeric_limits<double>::infinity();
    const std::string key = model_key(in.materials);
    for (const auto& [accuracy, rays] : searched_knobs(in)) {
        const CacheCost one = cache_cost(in, key, accuracy, rays, 1);
        *cache_min_seconds = std::min(*cache_min_seconds, one.cache_seconds + one.sample_seconds);
        const int spp = in.spp_fixed ? in.spp : samples_within(in, key, accuracy, rays, available);
        const CacheCost cost = cache_cost(in, key, accuracy, rays, std::max(spp, 1));
        if (spp < 1 || cost.cache_seconds + spp * cost.sample_seconds > available) {
            continue;
        }
        AutoPlan plan = cache_plan(in, accuracy, rays, spp);
        if (!best || plan.trusted_relmse < best->trusted_relmse) {
            best = plan;
        }
    }
    return best;
}

void add_temporal(const PlanInputs& in, AutoPlan* plan) {
    const bool wraps =
        plan->run.method == "ic" || plan->run.method == "rc" || plan->run.method == "sdrc";
    const bool glossy_list = std::any_of(plan->run.options.begin(), plan->run.options.end(),
                                         [](const auto& o) { return o.first == "--glossy"; });
    if (in.frames > 1 && wraps && !glossy_list && in.motion <= in.model->temporal_max_motion) {
        plan->temporal = true;
        plan->run.options.push_back({"--temporal", ""});
    }
}

void check_pilot_share(const PlanInputs& in) {
    if (in.budget > 0.0 && in.pilot_seconds > in.model->max_pilot_fraction * in.budget) {
        throw Error("--time " + number_text(in.budget) +
                        ": too short for --method auto (its pilot takes about " +
                        number_text(in.pilot_seconds, "%.2g") +
                        " s on this device; give at least " +
                        number_text(in.pilot_seconds / in.model->max_pilot_fraction, "%.2g") +
                        " s, or name a method)",
                    kExitUsage);
    }
}

}  // namespace

std::string model_key(const std::vector<MaterialChoice>& materials) {
    bool rc = false;
    for (const MaterialChoice& m : materials) {
        if (m.server == LobeServer::kSdrc) {
            return "sdrc";
        }
        rc = rc || m.server == LobeServer::kRadianceCache;
    }
    return rc ? "rc" : "ic";
}

MethodRun caching_run(const std::vector<MaterialChoice>& choices,
                      const std::vector<Material>& materials) {
    size_t glossy = 0;
    size_t rc = 0;
    size_t sdrc = 0;
    std::vector<GlossyServer> servers;
    for (const MaterialChoice& m : choices) {
        glossy += m.server != LobeServer::kDiffuse;
        rc += m.server == LobeServer::kRadianceCache;
        sdrc += m.server == LobeServer::kSdrc;
        servers.push_back(m.server == LobeServer::kRadianceCache ? GlossyServer::kRc
                          : m.server == LobeServer::kSdrc        ? GlossyServer::kSdrc
                                                                 : GlossyServer::kPath);
    }
    if (rc + sdrc == 0) {
        return {"ic", {}};
    }
    if (rc == glossy || sdrc == glossy) {
        return {rc == glossy ? "rc" : "sdrc", {}};
    }
    try {
        return {"ic", {{"--glossy", glossy_spec_of(servers, materials)}}};
    } catch (const Error&) {
        // A material the list cannot name (a ',' or '=' in its name, or a name two materials
        // share): one cache serves every glossy lobe, SDRC where any lobe needs it.
        return {sdrc > 0 ? "sdrc" : "rc", {}};
    }
}

AutoPlan choose_plan(const PlanInputs& in) {
    check_pilot_share(in);
    const double available =
        in.budget > 0.0 ? std::max(0.0, in.budget - in.pilot_seconds - in.tables_seconds) : 0.0;
    AutoPlan pt = path_tracer_plan(in, available);
    AutoPlan plan = pt;
    if (!in.cache) {
        plan.why = "no lobe to cache";
    } else if (in.budget <= 0.0) {
        plan = cache_plan(in, declared_default(in.cache_run.method, "--accuracy"),
                          static_cast<int>(declared_default(in.cache_run.method, "--ic-rays")),
                          in.spp);
    } else {
        double cheapest = 0.0;
        const std::optional<AutoPlan> cached = best_cache_plan(in, available, &cheapest);
        if (cached && cached->trusted_relmse < pt.predicted_relmse) {
            plan = *cached;
        } else if (cached) {
            plan.why = "the path tracer's error is predicted lower: " +
                       number_text(pt.predicted_relmse, "%.2e") + " against " +
                       number_text(cached->trusted_relmse, "%.2e");
        } else {
            plan.why = "the cheapest cache needs about " + number_text(cheapest, "%.3g") +
                       " s with one sample per pixel, " + number_text(available, "%.3g") +
                       " s are left";
        }
        plan.cache_min_seconds = cheapest;
    }
    plan.materials = in.materials;
    plan.pilot_seconds = in.pilot_seconds;
    plan.pt_relmse = in.noise.v_pt / std::max(pt.spp, 1);
    if (plan.caches()) {
        add_temporal(in, &plan);
    }
    return plan;
}

std::string AutoPlan::line() const {
    std::string text = "auto: ";
    if (!caches()) {
        text += "pt for every material (" + why + ")";
    } else {
        size_t diffuse = 0;
        std::string glossy;
        for (const MaterialChoice& m : materials) {
            if (m.server == LobeServer::kDiffuse) {
                ++diffuse;
            } else {
                glossy += std::string(", ") + lobe_server_name(m.server) + " for '" + m.name + "'";
            }
        }
        text += "ic for " + std::to_string(diffuse) + " diffuse material" +
                (diffuse == 1 ? "" : "s") + glossy;
        text += "; accuracy " + number_text(accuracy) + ", " + std::to_string(ic_rays) + " rays";
        if (temporal) {
            text += ", temporal";
        }
    }
    text += ", " + std::to_string(spp) + " spp; predicted " +
            number_text(predicted_seconds, "%.3g") + " s, relMSE " +
            number_text(predicted_relmse, "%.2e");
    if (caches()) {
        text += " (pt " + number_text(pt_relmse, "%.2e") + ")";
    }
    return text + "; pilot " + number_text(pilot_seconds, "%.2g") + " s";
}

nlohmann::json AutoPlan::json(const PlanInputs& in) const {
    nlohmann::json materials_json = nlohmann::json::array();
    for (const MaterialChoice& m : materials) {
        nlohmann::json entry = {{"name", m.name}, {"server", lobe_server_name(m.server)}};
        if (m.server != LobeServer::kDiffuse) {
            entry["exponent"] = m.exponent;
            entry["rc_fallback"] = m.rc_fallback;
        }
        materials_json.push_back(entry);
    }
    nlohmann::json pilot = {{"width", in.noise.size.width},
                            {"height", in.noise.size.height},
                            {"v_pt", in.noise.v_pt},
                            {"v_direct", in.noise.v_direct},
                            {"indirect_fraction", in.noise.indirect_fraction},
                            {"pt_rays_per_sample", in.noise.rays_per_sample},
                            {"seconds", pilot_seconds},
                            {"tables_seconds", in.tables_seconds}};
    if (in.cache) {
        pilot["cache"] = {{"run", in.cache->run.command_line()},
                          {"cache_rays", in.cache->cache_rays},
                          {"camera_rays_per_sample", in.cache->camera_rays_per_sample},
                          {"ic_rays", in.cache->ic_rays},
                          {"accuracy", in.cache->accuracy}};
    }
    nlohmann::json json = {{"method", run.method},
                           {"command", run.command_line()},
                           {"spp", spp},
                           {"materials", materials_json},
                           {"temporal", temporal},
                           {"budget", in.budget},
                           {"motion", in.motion},
                           {"predicted",
                            {{"seconds", predicted_seconds},
                             {"cache_seconds", predicted_cache_seconds},
                             {"relmse", predicted_relmse},
                             {"trusted_relmse", trusted_relmse},
                             {"pt_relmse", pt_relmse}}},
                           {"pilot", pilot},
                           {"model", in.model->fitted},
                           {"line", line()}};
    if (caches()) {
        json["accuracy"] = accuracy;
        json["ic_rays"] = ic_rays;
        json["default_knobs"] = default_knobs;
    } else {
        json["why"] = why;
    }
    return json;
}

}  // namespace rc
