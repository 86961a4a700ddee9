#include "methods/auto/auto_materials.h"

#include <algorithm>
#include <cmath>

namespace rc {

const char* lobe_server_name(LobeServer server) {
    switch (server) {
        case LobeServer::kDiffuse:
            return "ic";
        case LobeServer::kRadianceCache:
            return "rc";
        case LobeServer::kSdrc:
            return "sdrc";
        case LobeServer::kPath:
            return "pt";
    }
    return "?";
}

bool has_glossy_lobe(const Material& material) {
    const float specular =
        std::max({material.specular.x, material.specular.y, material.specular.z});
    return (material.kind == MaterialKind::kPhong || material.kind == MaterialKind::kWard) &&
           specular > 0.0f;
}

double glossy_exponent(const Material& material) {
    if (material.kind == MaterialKind::kWard) {
        return phong_exponent_of_alpha(std::sqrt(material.alpha_x * material.alpha_y));
    }
    return material.exponent;
}

namespace {

// rc's tables' share of directions left to Monte Carlo for `name`, or -1 when not listed.
double rc_fallback_of(const nlohmann::json* rc_materials, const std::string& name) {
    if (rc_materials == nullptr || !rc_materials->is_array()) {
        return -1.0;
    }
    for (const nlohmann::json& m : *rc_materials) {
        if (m.value("name", std::string()) == name) {
            return m.value("order", 0) > 0 ? m.value("fallback_fraction", 1.0) : 1.0;
        }
    }
    return -1.0;
}

}  // namespace

std::vector<MaterialChoice> choose_lobe_servers(const std::vector<Material>& materials,
                                                const AutoModel& model,
                                                const nlohmann::json* rc_materials) {
    std::vector<MaterialChoice> choices;
    for (const Material& material : materials) {
        MaterialChoice choice;
        choice.name = material.name;
        if (!is_reflectance_model(material)) {
            choice.server = LobeServer::kPath;  // a conductor or dielectric: no cache serves it
        } else if (has_glossy_lobe(material)) {
            choice.exponent = glossy_exponent(material);
            choice.rc_fallback = rc_fallback_of(rc_materials, material.name);
            if (choice.rc_fallback >= 0.0 && choice.rc_fallback <= model.rc_max_fallback) {
                choice.server = LobeServer::kRadianceCache;
            } else if (choice.exponent <= model.sdrc_max_exponent) {
                choice.server = LobeServer::kSdrc;
            } else {
                choice.server = LobeServer::kPath;
            }
        }
        choices.push_back(choice);
    }
    return choices;
}

}  // namespace rc
