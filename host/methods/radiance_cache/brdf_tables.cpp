#include "methods/radiance_cache/brdf_tables.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "device/context.h"
#include "methods/radiance_cache/gauss_legendre.h"
#include "util/error.h"

namespace rc {
namespace {

void require(bool ok, const std::string& option, const std::string& value,
             const std::string& range) {
    if (!ok) {
        throw Error(
            "BRDF table option " + option + " = " + value + " is out of range (" + range + ")",
            kExitUsage);
    }
}

// A material whose specular lobe radiance caching represents.
bool has_lobe(const Material& material) {
    const glm::vec3& ks = material.specular;
    return (material.kind == MaterialKind::kPhong || material.kind == MaterialKind::kWard) &&
           std::max({ks.r, ks.g, ks.b}) > 0.0f;
}

// The centre of texel t on the parabolic map, and the solid angle of directions around it
// (the map's area element: d omega = 4 / (1 + |p|^2)^2 dp).
struct TexelCentre {
    double x, y;
    bool inside() const { return x * x + y * y < 1.0; }
    double solid_angle(int resolution) const {
        const double r2 = x * x + y * y;
        const double size = 2.0 / resolution;
        return 4.0 / ((1.0 + r2) * (1.0 + r2)) * size * size;
    }
};

TexelCentre texel_centre(int t, int resolution) {
    const double size = 2.0 / resolution;
    return {-1.0 + (t % resolution + 0.5) * size, -1.0 + (t / resolution + 0.5) * size};
}

}  // namespace

const char* brdf_kind_name(int kind) {
    switch (kind) {
        case RC_BRDF_DIFFUSE:
            return "diffuse";
        case RC_BRDF_GLOSSY:
            return "glossy";
        case RC_BRDF_FALLBACK:
            return "fallback";
    }
    return "?";
}

void check_brdf_table_options(const BrdfTableOptions& o) {
    require(o.resolution >= 2 && o.resolution <= 256, "resolution", std::to_string(o.resolution),
            "2 to 256");
    require(o.max_order >= 1 && o.max_order <= RC_SH_MAX_ORDER, "max_order",
            std::to_string(o.max_order), "1 to " + std::to_string(RC_SH_MAX_ORDER));
    require(o.max_error > 0.0 && o.max_error < 1.0, "max_error", std::to_string(o.max_error),
            "above 0 and below 1");
    require(o.basis == RC_BASIS_SH || o.basis == RC_BASIS_HSH, "basis", std::to_string(o.basis),
            "0 (SH) or 1 (HSH)");
    require(o.theta_nodes >= RC_SH_MAX_ORDER && o.theta_nodes <= 1024, "theta_nodes",
            std::to_string(o.theta_nodes), std::to_string(RC_SH_MAX_ORDER) + " to 1024");
    require(o.phi_nodes >= 2 * RC_SH_MAX_ORDER && o.phi_nodes <= 4096, "phi_nodes",
            std::to_string(o.phi_nodes), std::to_string(2 * RC_SH_MAX_ORDER) + " to 4096");
}

BrdfTables::BrdfTables(Context& context, const std::vector<Material>& materials,
                       const BrdfTableOptions& options)
    : options_(options) {
    check_brdf_table_options(options);
    const int texels_per_table = options.resolution * options.resolution;
    int texels = 0;
    for (const Material& material : materials) {
        shared::BrdfTableInfo info{};
        info.first_texel = has_lobe(material) ? texels : -1;
        info.resolution = options.resolution;
        info.basis = options.basis;
        info.max_error = static_cast<float>(options.max_error);
        texels += has_lobe(material) ? texels_per_table : 0;
        infos_.push_back(info);
    }

    // The z = cos(theta_i) nodes over [0, 1], interleaved with their weights.
    const QuadratureRule rule = gauss_legendre(options.theta_nodes, 0.0, 1.0);
    std::vector<float> nodes;
    for (int j = 0; j < options.theta_nodes; ++j) {
        nodes.push_back(static_cast<float>(rule.nodes[j]));
        nodes.push_back(static_cast<float>(rule.weights[j]));
    }
    const Buffer<float> device_nodes(context, nodes, "rc_brdf_table_nodes");
    coefficients_ = Buffer<float>(context, static_cast<size_t>(texels) * RC_SH_MAX_COEFFICIENTS,
                                  "rc_brdf_table_coefficients");
    Buffer<float> errors(context, static_cast<size_t>(texels) * RC_SH_MAX_ORDER,
                         "rc_brdf_table_errors");
    Kernel kernel = context.kernel("radiance_cache/radiance_cache.cl", "rc_brdf_table_texels");
    for (size_t i = 0; i < materials.size(); ++i) {
        if (infos_[i].first_texel < 0) {
            continue;
        }
        shared::BrdfTableParams params{};
        params.first_texel = infos_[i].first_texel;
        params.resolution = options.resolution;
        params.basis = options.basis;
        params.theta_nodes = options.theta_nodes;
        params.phi_nodes = options.phi_nodes;
        context.launch(kernel, static_cast<size_t>(texels_per_table), to_device(materials[i]),
                       params, device_nodes, coefficients_, errors);
    }
    texel_errors_ = texels > 0 ? errors.download() : std::vector<float>{};
    choose_orders(materials);
    orders_ = Buffer<int>(context, texel_orders_.size(), "rc_brdf_table_orders");
    if (!texel_orders_.empty()) {
        orders_.upload(texel_orders_);
    }
    device_infos_ = Buffer<shared::BrdfTableInfo>(context, infos_, "rc_brdf_table_infos");
}

// The adaptive order (TVCG 2005 §4.1): per texel the lowest order within max_error, 0 beyond
// max_order; per material the highest texel order over the outgoing directions, the fraction of
// their solid angle left to Monte Carlo, and the kind.
void BrdfTables::choose_orders(const std::vector<Material>& materials) {
    const int g = options_.resolution;
    texel_orders_.assign(texel_errors_.size() / RC_SH_MAX_ORDER, 0);
    for (size_t t = 0; t < texel_orders_.size(); ++t) {
        for (int n = 1; n <= options_.max_order; ++n) {
            if (texel_errors_[t * RC_SH_MAX_ORDER + n - 1] <= options_.max_error) {
                texel_orders_[t] = n;
                break;
            }
        }
    }
    for (size_t i = 0; i < materials.size(); ++i) {
        shared::BrdfTableInfo& info = infos_[i];
        BrdfTableSummary summary;
        summary.name = materials[i].name;
        if (info.first_texel < 0) {
            summaries_.push_back(summary);
            continue;
        }
        double all = 0.0;
        double fallback = 0.0;
        summary.min_error_at_max_order = 1.0;
        for (int t = 0; t < g * g; ++t) {
            const TexelCentre centre = texel_centre(t, g);
            if (!centre.inside()) {
                continue;
            }
            const size_t at = static_cast<size_t>(info.first_texel) + t;
            const double solid_angle = centre.solid_angle(g);
            all += solid_angle;
            const int order = texel_orders_[at];
            if (order == 0) {
                fallback += solid_angle;
            }
            info.order = std::max(info.order, order);
            const double error = texel_errors_[at * RC_SH_MAX_ORDER + options_.max_order - 1];
            summary.min_error_at_max_order = std::min(summary.min_error_at_max_order, error);
            summary.max_error_at_max_order = std::max(summary.max_error_at_max_order, error);
        }
        info.fallback_fraction = static_cast<float>(fallback / all);
        info.kind = info.order == 0 ? RC_BRDF_FALLBACK : RC_BRDF_GLOSSY;
        summary.kind = info.kind;
        summary.order = info.order;
        summary.fallback_fraction = info.fallback_fraction;
        summaries_.push_back(summary);
    }
}

size_t BrdfTables::bytes() const {
    return device_infos_.bytes() + coefficients_.bytes() + orders_.bytes();
}

namespace {

// What the tables depend on: the options and every material's device form (its kernel input).
std::string tables_key(const std::vector<Material>& materials, const BrdfTableOptions& o) {
    char text[160];
    std::snprintf(text, sizeof(text), "brdf-tables %d %d %a %d %d %d:", o.resolution, o.max_order,
                  o.max_error, o.basis, o.theta_nodes, o.phi_nodes);
    std::string key = text;
    for (const Material& material : materials) {
        const shared::Material m = to_device(material);
        unsigned char bytes[sizeof m];
        std::memcpy(bytes, &m, sizeof m);
        for (unsigned char byte : bytes) {
            std::snprintf(text, sizeof(text), "%02x", byte);
            key += text;
        }
        key += ';';
    }
    return key;
}

}  // namespace

std::shared_ptr<const BrdfTables> shared_brdf_tables(Context& context,
                                                     const std::vector<Material>& materials,
                                                     const BrdfTableOptions& options, bool* built) {
    bool made = false;
    auto tables = context.derived<BrdfTables>(tables_key(materials, options), [&] {
        made = true;
        return std::make_shared<const BrdfTables>(context, materials, options);
    });
    if (built != nullptr) {
        *built = made;
    }
    return tables;
}

}  // namespace rc
