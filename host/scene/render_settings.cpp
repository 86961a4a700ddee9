#include "scene/render_settings.h"

#include <cmath>

#include "scene/json_parse.h"
#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

constexpr const char* kKeys = "method, spp, time, max_depth, rr_depth, seed, exposure";

long long integer_in(const nlohmann::json& value, const std::string& what, long long min,
                     long long max) {
    if (!value.is_number_integer() || value.get<long long>() < min ||
        value.get<long long>() > max) {
        throw Error(what + ": expected an integer in [" + std::to_string(min) + ", " +
                    std::to_string(max) + "], got " + describe_json(value));
    }
    return value.get<long long>();
}

double number_in(const nlohmann::json& value, const std::string& what, double min, double max) {
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < min ||
        value.get<double>() > max) {
        throw Error(what + ": expected a number in [" + std::to_string(min) + ", " +
                    std::to_string(max) + "], got " + describe_json(value));
    }
    return value.get<double>();
}

}  // namespace

void RenderSettings::set(const std::string& key, const nlohmann::json& value,
                         const std::string& where) {
    const std::string what = where + ": " + excerpt(key);
    if (key == "method") {
        if (!value.is_string()) {
            throw Error(what + ": expected a string, got " + describe_json(value));
        }
        method = value.get<std::string>();
    } else if (key == "spp") {
        spp = static_cast<int>(integer_in(value, what, 1, 1 << 24));
    } else if (key == "time") {
        time = number_in(value, what, 0.0, 1e7);
    } else if (key == "max_depth") {
        max_depth = static_cast<int>(integer_in(value, what, 0, 1024));
    } else if (key == "rr_depth") {
        rr_depth = static_cast<int>(integer_in(value, what, 1, 1024));
    } else if (key == "seed") {
        seed = static_cast<uint64_t>(integer_in(value, what, 0, (1LL << 62)));
    } else if (key == "exposure") {
        exposure = static_cast<float>(number_in(value, what, -64.0, 64.0));
    } else {
        throw Error(where + ": unknown render setting '" + excerpt(key) + "' (known: " + kKeys +
                    ")");
    }
}

void RenderSettings::apply_override(const std::string& assignment) {
    const size_t equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0) {
        throw Error("-D " + excerpt(assignment) + ": expected key=value", 2);
    }
    const std::string key = assignment.substr(0, equals);
    const std::string text = assignment.substr(equals + 1);
    nlohmann::json value = text;
    try {
        const nlohmann::json parsed = nlohmann::json::parse(text);
        if (parsed.is_number()) {
            value = parsed;
        }
    } catch (const nlohmann::json::exception&) {
        // Not a number: keep the text as a string.
    }
    try {
        set(key, value, "-D");
    } catch (const Error& error) {
        throw Error(error.what(), 2);
    }
}

}  // namespace rc
