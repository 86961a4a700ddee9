// Materials (kernels/common/material.h): chi-square goodness of fit of every sampler against its
// pdf, sample/pdf/eval consistency, and directional albedo <= 1 for every BRDF.
#include "scene/material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "chi_square.h"
#include "material_probes.h"
#include "shared/types.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Case {
    std::string name;
    Material material;
};

std::vector<Case> cases() {
    std::vector<Case> list;
    Material diffuse;
    diffuse.diffuse = glm::vec3(0.8f);
    list.push_back({"diffuse", diffuse});
    for (float exponent : {1.0f, 12.0f, 60.0f}) {
        Material phong;
        phong.kind = MaterialKind::kPhong;
        phong.diffuse = glm::vec3(0.3f);
        phong.specular = glm::vec3(0.7f);
        phong.exponent = exponent;
        list.push_back({"phong n=" + std::to_string(static_cast<int>(exponent)), phong});
    }
    Material phong_only;
    phong_only.kind = MaterialKind::kPhong;
    phong_only.diffuse = glm::vec3(0.0f);
    phong_only.specular = glm::vec3(1.0f);
    phong_only.exponent = 20.0f;
    list.push_back({"phong specular only", phong_only});
    for (const auto& [ax, ay] : {std::pair{0.1f, 0.1f}, std::pair{0.25f, 0.25f},
                                 std::pair{0.1f, 0.4f}, std::pair{0.6f, 0.3f}}) {
        Material ward;
        ward.kind = MaterialKind::kWard;
        ward.diffuse = glm::vec3(0.2f);
        ward.specular = glm::vec3(0.8f);
        ward.alpha_x = ax;
        ward.alpha_y = ay;
        list.push_back(
            {"ward " + std::to_string(ax).substr(0, 4) + "/" + std::to_string(ay).substr(0, 4),
             ward});
    }
    Material ward_only = list.back().material;
    ward_only.diffuse = glm::vec3(0.0f);
    ward_only.specular = glm::vec3(1.0f);
    list.push_back({"ward specular only", ward_only});
    for (const auto& [ax, ay] : {std::pair{0.3f, 0.3f}, std::pair{0.1f, 0.4f}}) {
        Material conductor;
        conductor.kind = MaterialKind::kConductor;
        conductor.diffuse = glm::vec3(0.0f);
        conductor.specular = glm::vec3(1.0f);
        conductor.eta = glm::vec3(0.2f, 0.92f, 1.1f);
        conductor.k = glm::vec3(3.9f, 2.45f, 2.14f);
        conductor.alpha_x = ax;
        conductor.alpha_y = ay;
        list.push_back(
            {"conductor " + std::to_string(ax).substr(0, 4) + "/" + std::to_string(ay).substr(0, 4),
             conductor});
    }
    // A rough dielectric seen from outside (eta 1.5) and from inside (eta 1 / 1.5).
    for (float ior : {1.5f, 1.0f / 1.5f}) {
        Material glass;
        glass.kind = MaterialKind::kDielectric;
        glass.diffuse = glm::vec3(0.0f);
        glass.specular = glm::vec3(1.0f);
        glass.ior = ior;
        glass.alpha_x = glass.alpha_y = 0.3f;
        list.push_back({"dielectric 0.3 eta " + std::to_string(ior).substr(0, 4), glass});
    }
    Material lampshade;
    lampshade.kind = MaterialKind::kDiffuseTransmission;
    lampshade.diffuse = glm::vec3(0.0f);
    lampshade.specular = glm::vec3(0.5f, 0.3f, 0.2f);
    lampshade.transmittance = glm::vec3(0.3f, 0.4f, 0.6f);
    list.push_back({"diffuse transmission", lampshade});
    return list;
}

shared::float4 wo_at(float theta_degrees, float phi_degrees) {
    const float t = theta_degrees * static_cast<float>(kPi) / 180.0f;
    const float p = phi_degrees * static_cast<float>(kPi) / 180.0f;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t), 0.0f};
}

// Bins over the sphere, uniform in theta (an even count, so the horizon is a bin edge) and phi.
struct SphereBins {
    int theta = 16;
    int phi = 32;
    int count() const { return theta * phi; }
    int of(const shared::float4& d) const {
        const double t = std::acos(std::clamp(static_cast<double>(d.z), -1.0, 1.0));
        double phi_angle = std::atan2(d.y, d.x);
        if (phi_angle < 0.0) {
            phi_angle += 2.0 * kPi;
        }
        const int i = std::min(static_cast<int>(t / kPi * theta), theta - 1);
        const int j = std::min(static_cast<int>(phi_angle / (2.0 * kPi) * phi), phi - 1);
        return i * phi + j;
    }
};

// 4-point Gauss-Legendre nodes and weights on [-1, 1].
const double kGaussNodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                               0.8611363115940526};
const double kGaussWeights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                 0.3478548451374538};

// Quadrature of a function over every bin: each bin split into `cells` x `cells` cells with 4 x 4
// Gauss-Legendre points in (theta, phi) each, weights including the sin(theta) Jacobian; the
// points of bin b are [b * points_per_bin, (b + 1) * points_per_bin). Fine enough for the
// narrowest lobe tested (Ward alpha 0.1 at 87 degrees from the normal, about 1 degree wide).
struct Quadrature {
    std::vector<shared::float4> directions;
    std::vector<double> weights;
    int points_per_bin = 0;
};

Quadrature bin_quadrature(const SphereBins& bins, int cells) {
    Quadrature q;
    q.points_per_bin = cells * cells * 16;
    const double d_theta = kPi / bins.theta / cells;
    const double d_phi = 2.0 * kPi / bins.phi / cells;
    for (int i = 0; i < bins.theta; ++i) {
        for (int j = 0; j < bins.phi; ++j) {
            for (int ci = 0; ci < cells; ++ci) {
                for (int cj = 0; cj < cells; ++cj) {
                    for (int a = 0; a < 4; ++a) {
                        for (int b = 0; b < 4; ++b) {
                            const double theta =
                                (i * cells + ci + 0.5 + 0.5 * kGaussNodes[a]) * d_theta;
                            const double phi =
                                (j * cells + cj + 0.5 + 0.5 * kGaussNodes[b]) * d_phi;
                            q.directions.push_back(
                                {static_cast<float>(std::sin(theta) * std::cos(phi)),
                                 static_cast<float>(std::sin(theta) * std::sin(phi)),
                                 static_cast<float>(std::cos(theta)), 0.0f});
                            q.weights.push_back(0.25 * kGaussWeights[a] * kGaussWeights[b] *
                                                d_theta * d_phi * std::sin(theta));
                        }
                    }
                }
            }
        }
    }
    return q;
}

std::vector<shared::float4> evaluate(const shared::Material& m, shared::float4 wo,
                                     const std::vector<shared::float4>& directions) {
    return test::material_values(m, wo, directions);
}

using test::MaterialSamples;

MaterialSamples sample(const shared::Material& m, shared::float4 wo, size_t count, unsigned seed) {
    return test::material_samples(m, wo, count, seed);
}

const float kAngles[][2] = {{0.0f, 0.0f}, {35.0f, 20.0f}, {70.0f, 200.0f}, {87.0f, 120.0f}};

// The histogram of 2^20 samples against N * integral of the pdf over each bin; failed samples
// form one more bin, expected N * (1 - integral of the pdf). The test fails below p = 1e-4 (a
// false alarm once in 10 000 runs per case).
TEST(Material, SamplersMatchTheirPdfByChiSquare) {
    SphereBins bins;
    bins.theta = 16;
    bins.phi = 32;
    const Quadrature quadrature = bin_quadrature(bins, 16);
    const int per_bin = quadrature.points_per_bin;
    const size_t n = size_t{1} << 20;
    unsigned seed = 1;
    for (const Case& c : cases()) {
        const shared::Material m = to_device(c.material);
        for (const auto& angle : kAngles) {
            SCOPED_TRACE(c.name + " at theta " + std::to_string(angle[0]));
            const shared::float4 wo = wo_at(angle[0], angle[1]);
            const std::vector<shared::float4> pdf = evaluate(m, wo, quadrature.directions);
            std::vector<double> expected(bins.count() + 1, 0.0);
            double total = 0.0;
            for (int b = 0; b < bins.count(); ++b) {
                double integral = 0.0;
                for (int k = 0; k < per_bin; ++k) {
                    const size_t at = static_cast<size_t>(b) * per_bin + k;
                    integral += pdf[at].w * quadrature.weights[at];
                }
                expected[b] = integral * n;
                total += integral;
            }
            ASSERT_LE(total, 1.0 + 1e-3) << "pdf integrates to more than 1";
            expected[bins.count()] = std::max(0.0, 1.0 - total) * n;
            const MaterialSamples s = sample(m, wo, n, seed++);
            std::vector<double> observed(bins.count() + 1, 0.0);
            for (const shared::float4& d : s.directions) {
                observed[d.w < 0.0f ? bins.count() : bins.of(d)] += 1.0;
            }
            const test::ChiSquareResult chi = test::chi_square_test(observed, expected);
            EXPECT_GT(chi.p_value, 1e-4) << chi.summary();
            if (chi.p_value <= 1e-4) {
                for (int b = 0; b <= bins.count(); ++b) {
                    const double d = observed[b] - expected[b];
                    if (expected[b] > 5 && d * d / expected[b] > 30) {
                        std::printf("bin %d (theta %d phi %d): observed %.0f expected %.1f\n", b,
                                    b / bins.phi, b % bins.phi, observed[b], expected[b]);
                    }
                }
            }
        }
    }
}

// Each successful sample reports the pdf and BSDF value that pdf() and eval() give for its
// direction, and lies above the surface unless the material transmits.
TEST(Material, SamplesAgreeWithPdfAndEval) {
    for (const Case& c : cases()) {
        const shared::Material m = to_device(c.material);
        for (const auto& angle : kAngles) {
            SCOPED_TRACE(c.name + " at theta " + std::to_string(angle[0]));
            const shared::float4 wo = wo_at(angle[0], angle[1]);
            const MaterialSamples s = sample(m, wo, 4096, 99);
            std::vector<shared::float4> ok;
            std::vector<shared::float4> ok_values;
            for (size_t i = 0; i < s.directions.size(); ++i) {
                if (s.directions[i].w >= 0.0f) {
                    ok.push_back(s.directions[i]);
                    ok_values.push_back(s.values[i]);
                }
            }
            ASSERT_GT(ok.size(), 100u);
            const std::vector<shared::float4> eval = evaluate(m, wo, ok);
            for (size_t i = 0; i < ok.size(); ++i) {
                if (!transmits(c.material)) {
                    EXPECT_GT(ok[i].z, 0.0f);
                }
                EXPECT_NEAR(std::sqrt(ok[i].x * ok[i].x + ok[i].y * ok[i].y + ok[i].z * ok[i].z),
                            1.0f, 1e-5f);
                EXPECT_NEAR(ok[i].w, eval[i].w, 1e-4f * eval[i].w) << "pdf of sample " << i;
                EXPECT_NEAR(ok_values[i].x, eval[i].x, 1e-4f * eval[i].x) << "f of sample " << i;
                EXPECT_GT(eval[i].w, 0.0f);
            }
        }
    }
}

// Directional albedo: the integral of f cos over the hemisphere (midpoint rule, 256 x 512), at
// most 1 for every BRDF and incident angle, and the diffuse albedo exactly for Lambert.
TEST(Material, DirectionalAlbedoIsAtMostOne) {
    const test::DirectionGrid grid = test::direction_grid(256, 512, 0.5 * kPi);
    for (const Case& c : cases()) {
        Material full = c.material;
        if (full.kind != MaterialKind::kDiffuse) {
            // The worst case: all energy available to the lobes.
            const glm::vec3 total = full.diffuse + full.specular;
            full.diffuse /= std::max({total.r, total.g, total.b});
            full.specular /= std::max({total.r, total.g, total.b});
        }
        const shared::Material m = to_device(full);
        for (float theta : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
            SCOPED_TRACE(c.name + " at theta " + std::to_string(theta));
            const shared::float4 wo = wo_at(theta, 33.0f);
            const std::vector<shared::float4> f = evaluate(m, wo, grid.directions);
            double albedo = 0.0;
            for (size_t i = 0; i < grid.directions.size(); ++i) {
                albedo += f[i].x * grid.directions[i].z * grid.weights[i];
            }
            EXPECT_LE(albedo, 1.0 + 2e-3);
            if (full.kind == MaterialKind::kDiffuse) {
                EXPECT_NEAR(albedo, full.diffuse.r, 2e-3);
            }
        }
    }
}

}  // namespace
}  // namespace rc
