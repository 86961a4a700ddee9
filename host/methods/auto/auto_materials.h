// Which method serves each material's lobes under `--method auto` (docs/auto.md, "Per
// material"): irradiance caching the diffuse lobes of every material; a glossy lobe radiance
// caching where its BRDF tables represent it (the adaptive order, TVCG 2005 §4.1), else SDRC up
// to the sharpest lobe SDRC is measured to serve, else path tracing.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "methods/auto/auto_model.h"
#include "scene/material.h"

namespace rc {

enum class LobeServer { kDiffuse, kRadianceCache, kSdrc, kPath };

const char* lobe_server_name(LobeServer server);  // "ic", "rc", "sdrc", "pt"

struct MaterialChoice {
    std::string name;
    LobeServer server = LobeServer::kDiffuse;  // of its glossy lobe (kDiffuse: it has none)
    double exponent = 0.0;  // the glossy lobe's Phong exponent (Ward: its equivalent)
    double rc_fallback =
        -1.0;  // the share of directions rc's tables leave to Monte Carlo (-1: not asked)
};

// Whether the material has a glossy lobe (a specular lobe with some reflectance).
bool has_glossy_lobe(const Material& material);

// The glossy lobe's Phong exponent: phong's own; ward's of alpha = sqrt(alpha_x alpha_y).
double glossy_exponent(const Material& material);

// One choice per material, in the scene's order. `rc_materials`: the "materials" list of radiance
// caching's statistics ({name, order, fallback_fraction}), or null when the scene has no glossy
// lobe.
std::vector<MaterialChoice> choose_lobe_servers(const std::vector<Material>& materials,
                                                const AutoModel& model,
                                                const nlohmann::json* rc_materials);

}  // namespace rc
