#include "sh_quadrature.h"

#include <cmath>
#include <numbers>

#include "device/buffer.h"
#include "methods/radiance_cache/gauss_legendre.h"

namespace rc::test {

double legendre(int l, double x) {
    double p_prev = 1.0;
    double p = x;
    if (l == 0) {
        return 1.0;
    }
    for (int k = 1; k < l; ++k) {
        const double next = ((2.0 * k + 1.0) * x * p - k * p_prev) / (k + 1.0);
        p_prev = p;
        p = next;
    }
    return p;
}

DirectionQuadrature product_quadrature(double z_min, int theta_nodes, int phi_nodes) {
    const QuadratureRule rule = gauss_legendre(theta_nodes, z_min, 1.0);
    DirectionQuadrature q;
    const double d_phi = 2.0 * std::numbers::pi / phi_nodes;
    for (int j = 0; j < theta_nodes; ++j) {
        const double z = rule.nodes[j];
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        for (int k = 0; k < phi_nodes; ++k) {
            const double phi = (k + 0.5) * d_phi;
            q.directions.push_back({static_cast<float>(s * std::cos(phi)),
                                    static_cast<float>(s * std::sin(phi)), static_cast<float>(z),
                                    0.0f});
            q.weights.push_back(rule.weights[j] * d_phi);
        }
    }
    return q;
}

shared::float4 random_direction(std::mt19937& rng) {
    std::normal_distribution<double> normal;
    double x, y, z, length;
    do {
        x = normal(rng);
        y = normal(rng);
        z = normal(rng);
        length = std::sqrt(x * x + y * y + z * z);
    } while (length < 1e-6);
    return {static_cast<float>(x / length), static_cast<float>(y / length),
            static_cast<float>(z / length), 0.0f};
}

std::vector<double> random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> normal;
    double w = normal(rng), x = normal(rng), y = normal(rng), z = normal(rng);
    const double length = std::sqrt(w * w + x * x + y * y + z * z);
    w /= length;
    x /= length;
    y /= length;
    z /= length;
    return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
            2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

std::vector<float> device_basis(Context& context, int basis, int order,
                                const std::vector<shared::float4>& directions) {
    Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_basis_probe");
    const Buffer<shared::float4> in(context, directions, "directions");
    Buffer<float> out(context, directions.size() * order * order, "basis");
    context.launch(kernel, directions.size(), basis, order, in, out);
    return out.download();
}

double record_hemisphere_albedo(Context& context, const Material& material, shared::float4 wo,
                                const std::vector<double>& r) {
    const DirectionQuadrature q = product_quadrature(0.0, 96, 192);
    Kernel kernel = context.kernel("material_probe.cl", "material_eval_probe");
    const Buffer<shared::float4> in(context, q.directions, "directions");
    Buffer<shared::float4> out(context, q.directions.size(), "values");
    context.launch(kernel, q.directions.size(), to_device(material), wo, in, out);
    const std::vector<shared::float4> f = out.download();
    double sum = 0.0;
    for (size_t k = 0; k < q.weights.size(); ++k) {
        const shared::float4& d = q.directions[k];
        const double record_z = r[2] * d.x + r[5] * d.y + r[8] * d.z;
        if (record_z > 0.0) {
            sum += q.weights[k] * f[k].x * d.z;
        }
    }
    return sum;
}

}  // namespace rc::test
