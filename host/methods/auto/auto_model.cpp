#include "methods/auto/auto_model.h"

#include "util/error.h"

namespace rc {

extern const char kAutoModelJson[];  // generated from auto_model.json (host/CMakeLists.txt)

namespace {

const nlohmann::json& member(const nlohmann::json& json, const std::string& key,
                             const std::string& path) {
    if (!json.is_object() || !json.contains(key)) {
        throw Error("auto model: missing key '" + path + key + "'");
    }
    return json.at(key);
}

double positive_number(const nlohmann::json& json, const std::string& key,
                       const std::string& path) {
    const nlohmann::json& value = member(json, key, path);
    if (!value.is_number() || value.get<double>() < 0.0) {
        throw Error("auto model: '" + path + key + "' must be a non-negative number");
    }
    return value.get<double>();
}

template <class T>
std::vector<T> number_list(const nlohmann::json& json, const std::string& key,
                           const std::string& path) {
    const nlohmann::json& value = member(json, key, path);
    if (!value.is_array() || value.empty()) {
        throw Error("auto model: '" + path + key + "' must be a non-empty list");
    }
    std::vector<T> list;
    for (const nlohmann::json& item : value) {
        if (!item.is_number() || item.get<double>() <= 0.0) {
            throw Error("auto model: '" + path + key + "' must hold positive numbers");
        }
        list.push_back(item.get<T>());
    }
    return list;
}

}  // namespace

const AutoCostModel& AutoModel::cost_of(const std::string& method) const {
    const auto found = cost.find(method);
    if (found == cost.end()) {
        throw Error("auto model: no cost constants for '" + method + "'");
    }
    return found->second;
}

const AutoErrorModel& AutoModel::error_of(const std::string& method) const {
    const auto found = error.find(method);
    if (found == error.end()) {
        throw Error("auto model: no error constants for '" + method + "'");
    }
    return found->second;
}

AutoModel parse_auto_model(const nlohmann::json& json) {
    AutoModel model;
    const nlohmann::json& pilot = member(json, "pilot", "");
    model.pilot_divisor = static_cast<int>(positive_number(pilot, "divisor", "pilot."));
    model.pilot_min_side = static_cast<int>(positive_number(pilot, "min_side", "pilot."));
    model.pilot_pt_spp = static_cast<int>(positive_number(pilot, "pt_spp", "pilot."));
    model.pilot_rays_divisor = static_cast<int>(positive_number(pilot, "rays_divisor", "pilot."));
    model.max_pilot_fraction = positive_number(pilot, "max_budget_fraction", "pilot.");
    if (model.pilot_divisor < 1 || model.pilot_min_side < 1 || model.pilot_pt_spp < 1 ||
        model.pilot_rays_divisor < 1) {
        throw Error("auto model: the pilot's divisors, side and samples must be at least 1");
    }
    const nlohmann::json& knobs = member(json, "knobs", "");
    model.accuracies = number_list<double>(knobs, "accuracy", "knobs.");
    model.ic_rays = number_list<int>(knobs, "ic_rays", "knobs.");
    for (const auto& [method, constants] : member(json, "cost", "").items()) {
        const std::string path = "cost." + method + ".";
        model.cost[method] = {
            positive_number(constants, "scale", path), positive_number(constants, "gamma", path),
            positive_number(constants, "rho", path), positive_number(constants, "alpha", path),
            positive_number(constants, "sigma", path)};
    }
    for (const auto& [method, constants] : member(json, "error", "").items()) {
        const std::string path = "error." + method + ".";
        model.error[method] = {
            positive_number(constants, "delta", path), positive_number(constants, "phi", path),
            positive_number(constants, "beta", path), positive_number(constants, "kappa", path),
            positive_number(constants, "spread", path)};
        if (model.error[method].spread < 1.0) {
            throw Error("auto model: " + path + "spread must be at least 1");
        }
    }
    const nlohmann::json& glossy = member(json, "glossy", "");
    model.rc_max_fallback = positive_number(glossy, "rc_max_fallback", "glossy.");
    model.sdrc_max_exponent = positive_number(glossy, "sdrc_max_exponent", "glossy.");
    model.temporal_max_motion =
        positive_number(member(json, "temporal", ""), "max_motion", "temporal.");
    const nlohmann::json& fitted = member(json, "fitted", "");
    model.fitted = fitted.is_string() ? fitted.get<std::string>() : fitted.dump();
    return model;
}

const AutoModel& auto_model() {
    static const AutoModel model = parse_auto_model(nlohmann::json::parse(kAutoModelJson));
    return model;
}

}  // namespace rc
