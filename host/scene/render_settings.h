// Render defaults: from the scene's "render" block, overridden by -D key=value and then by the
// command line's own options.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace rc {

struct RenderSettings {
    std::string method = "pt";
    int spp = 16;
    double time = 0.0;  // seconds; > 0 renders until the time is spent instead of to spp
    int max_depth = 64;
    int rr_depth = 3;
    uint64_t seed = 0;
    float exposure = 0.0f;

    // Sets one key from a JSON value; `where` names the source in errors ("scene.json: render"
    // or "-D"). Unknown keys and bad values throw Error.
    void set(const std::string& key, const nlohmann::json& value, const std::string& where);
    // Applies "key=value" (the value parsed as JSON when it is a number, else as a string).
    void apply_override(const std::string& assignment);
};

}  // namespace rc
