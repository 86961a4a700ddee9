#include "material_probes.h"

#include <cmath>

#include "test_support.h"

namespace rc::test {

std::vector<shared::float4> material_values(const shared::Material& material, shared::float4 wo,
                                            const std::vector<shared::float4>& directions) {
    Context& context = shared_context();
    Kernel kernel = context.kernel("material_probe.cl", "material_eval_probe");
    const Buffer<shared::float4> in(context, directions, "directions");
    Buffer<shared::float4> out(context, directions.size(), "values");
    context.launch(kernel, directions.size(), material, wo, in, out);
    return out.download();
}

MaterialSamples material_samples(const shared::Material& material, shared::float4 wo, size_t count,
                                 unsigned seed) {
    Context& context = shared_context();
    Kernel kernel = context.kernel("material_probe.cl", "material_sample_probe");
    Buffer<shared::float4> directions(context, count, "samples");
    Buffer<shared::float4> values(context, count, "sample_values");
    context.launch(kernel, count, material, wo, seed, directions, values);
    return {directions.download(), values.download()};
}

DirectionGrid direction_grid(int theta_steps, int phi_steps, double theta_max) {
    DirectionGrid g;
    const double d_theta = theta_max / theta_steps;
    const double d_phi = 2.0 * 3.14159265358979323846 / phi_steps;
    for (int i = 0; i < theta_steps; ++i) {
        const double theta = (i + 0.5) * d_theta;
        for (int j = 0; j < phi_steps; ++j) {
            const double phi = (j + 0.5) * d_phi;
            g.directions.push_back({static_cast<float>(std::sin(theta) * std::cos(phi)),
                                    static_cast<float>(std::sin(theta) * std::sin(phi)),
                                    static_cast<float>(std::cos(theta)), 0.0f});
            g.weights.push_back(std::sin(theta) * d_theta * d_phi);
        }
    }
    return g;
}

}  // namespace rc::test
