// Monte Carlo projection of radiance onto the (hemi)spherical harmonics
// (kernels/radiance_cache/rc_projection.h) over stratified uniform hemisphere samples: a
// constant, a clamped cosine lobe and single basis functions project to their closed forms, the
// mean over independent records within the bound of its sample standard deviation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sh_quadrature.h"
#include "shared/spherical_harmonics.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kOrder = RC_SH_MAX_ORDER;
constexpr int kCount = kOrder * kOrder;
constexpr int kStrataM = 16;
constexpr int kStrataN = 64;  // N = 4M, as the course suggests
constexpr int kRecords = 64;
const shared::float4 kColour = {1.0f, 0.5f, 2.0f, 0.0f};

// Test radiance (kernels/radiance_cache/rc_probe.cl).
constexpr int kConstant = 0;
constexpr int kCosinePower = 1;
constexpr int kBasisFunction = 2;

struct TestRadiance {
    int mode = kConstant;
    int basis = RC_BASIS_SH;
    int function = 0;
    float exponent = 0.0f;
};

// Coefficients (r, g, b vectors of kCount) of kRecords records, record r's at [r * 3 kCount ...).
std::vector<float> project(Context& context, int basis, const TestRadiance& radiance,
                           unsigned key) {
    Kernel cells_kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_cells_probe");
    Kernel projection = context.kernel("radiance_cache/rc_probe.cl", "rc_projection_probe");
    const size_t cell_count = static_cast<size_t>(kRecords) * kStrataM * kStrataN;
    Buffer<shared::float4> cells(context, cell_count, "cells");
    context.launch(cells_kernel, cell_count, kStrataM, kStrataN, key, 0u, radiance.mode,
                   radiance.basis, radiance.function, radiance.exponent, kColour, cells);
    Buffer<float> out(context, static_cast<size_t>(kRecords) * 3 * kCount, "coefficients");
    context.launch(projection, kRecords, kStrataM, kStrataN, key, 0u, basis, kOrder, cells, out);
    return out.download();
}

// Every coefficient's mean over the records lies within 6 standard errors (the records are
// independent) of expected[i] * colour, plus float rounding.
void expect_projects_to(int basis, const TestRadiance& radiance,
                        const std::vector<double>& expected) {
    const std::vector<float> c = project(test::shared_context(), basis, radiance, 1234u);
    const float colour[3] = {kColour.x, kColour.y, kColour.z};
    for (int channel = 0; channel < 3; ++channel) {
        for (int i = 0; i < kCount; ++i) {
            double sum = 0.0, sum2 = 0.0;
            for (int r = 0; r < kRecords; ++r) {
                const double v = c[(r * 3 + channel) * kCount + i];
                sum += v;
                sum2 += v * v;
            }
            const double mean = sum / kRecords;
            const double variance = std::max(0.0, (sum2 - sum * mean) / (kRecords - 1));
            const double bound = 6.0 * std::sqrt(variance / kRecords) + 2e-5 * colour[2];
            EXPECT_NEAR(mean, expected[i] * colour[channel], bound)
                << "channel " << channel << " coefficient " << i;
        }
    }
}

// P_n(0): 0 for odd n, (-1)^(n/2) (n-1)!! / n!! for even n.
double legendre_at_zero(int n) {
    if (n % 2 == 1) {
        return 0.0;
    }
    double p = 1.0;
    for (int k = 1; k <= n / 2; ++k) {
        p *= -(2.0 * k - 1.0) / (2.0 * k);
    }
    return p;
}

// Closed forms of the hemispherical integrals of Legendre polynomials: integral over [0, 1] of
// P_l (1 for l = 0, (P_{l-1}(0) - P_{l+1}(0)) / (2l + 1) otherwise) and of z P_l (1/2, 1/3,
// 0 for odd l >= 3, (-1)^(l/2+1) (l-2)! / (2^l (l/2-1)! (l/2+1)!) for even l >= 2).
double integral_of_legendre(int l) {
    return l == 0 ? 1.0 : (legendre_at_zero(l - 1) - legendre_at_zero(l + 1)) / (2 * l + 1);
}

double integral_of_z_legendre(int l) {
    if (l == 0) {
        return 0.5;
    }
    if (l == 1) {
        return 1.0 / 3.0;
    }
    if (l % 2 == 1) {
        return 0.0;
    }
    const int h = l / 2;
    return (h % 2 == 0 ? -1.0 : 1.0) * std::tgamma(l - 1) /
           (std::pow(2.0, l) * std::tgamma(h) * std::tgamma(h + 2));
}

// Zonal functions project onto the m = 0 harmonics only: c_l^0 = 2 pi K_l integral of g(z) P_l(z),
// K_l = sqrt((2l + 1) / 4pi).
std::vector<double> zonal_sh(double (*integral)(int)) {
    std::vector<double> c(kCount, 0.0);
    for (int l = 0; l < kOrder; ++l) {
        c[shared::rc_sh_index(l, 0)] = 2 * kPi * std::sqrt((2 * l + 1) / (4 * kPi)) * integral(l);
    }
    return c;
}

TEST(ShProjection, ConstantRadianceProjectsToItsClosedForm) {
    expect_projects_to(RC_BASIS_SH, {}, zonal_sh(integral_of_legendre));
    // HSH: the constant is a multiple of H_0^0 = 1 / sqrt(2 pi).
    std::vector<double> hsh(kCount, 0.0);
    hsh[0] = std::sqrt(2 * kPi);
    expect_projects_to(RC_BASIS_HSH, {}, hsh);
}

TEST(ShProjection, ClampedCosineLobeProjectsToItsClosedForm) {
    TestRadiance cosine;
    cosine.mode = kCosinePower;
    cosine.exponent = 1.0f;
    expect_projects_to(RC_BASIS_SH, cosine, zonal_sh(integral_of_z_legendre));
    // HSH: z = (1 + (2z - 1)) / 2 lies in bands 0 and 1: c_0 = 2 pi H_0^0 / 2,
    // c_(1,0) = 2 pi sqrt(3 / 2pi) integral of z (2z - 1) = 2 pi sqrt(3 / 2pi) / 6.
    std::vector<double> hsh(kCount, 0.0);
    hsh[0] = 2 * kPi / std::sqrt(2 * kPi) / 2;
    hsh[shared::rc_sh_index(1, 0)] = 2 * kPi * std::sqrt(3 / (2 * kPi)) / 6;
    expect_projects_to(RC_BASIS_HSH, cosine, hsh);
}

TEST(ShProjection, SingleHemisphericalHarmonicsProjectToUnitVectors) {
    for (int function : {0, 3, 8, 24, 57, 99}) {
        SCOPED_TRACE("H index " + std::to_string(function));
        TestRadiance radiance;
        radiance.mode = kBasisFunction;
        radiance.basis = RC_BASIS_HSH;
        radiance.function = function;
        std::vector<double> expected(kCount, 0.0);
        expected[function] = 1.0;
        expect_projects_to(RC_BASIS_HSH, radiance, expected);
    }
}

// A spherical harmonic seen on the hemisphere only projects to its row of the hemispherical Gram
// matrix (1/2 on the diagonal, 0 against functions of other m or of the same parity of l + l'),
// computed by an exact host quadrature.
TEST(ShProjection, SingleSphericalHarmonicsProjectToTheirHemisphericalGramRow) {
    const test::DirectionQuadrature q = test::product_quadrature(0.0, 16, 32);
    for (int function : {0, 2, 5, 12, 30, 77}) {
        SCOPED_TRACE("Y index " + std::to_string(function));
        std::vector<double> expected(kCount, 0.0);
        for (size_t i = 0; i < q.weights.size(); ++i) {
            float y[kCount];
            shared::rc_sh_eval(q.directions[i].x, q.directions[i].y, q.directions[i].z, kOrder, y);
            for (int k = 0; k < kCount; ++k) {
                expected[k] += q.weights[i] * y[function] * y[k];
            }
        }
        EXPECT_NEAR(expected[function], 0.5, 1e-6);
        TestRadiance radiance;
        radiance.mode = kBasisFunction;
        radiance.function = function;
        expect_projects_to(RC_BASIS_SH, radiance, expected);
    }
}

// Same key, different work-group size: bitwise the same coefficients.
TEST(ShProjection, IsDeterministicAcrossWorkGroupSizes) {
    TestRadiance cosine;
    cosine.mode = kCosinePower;
    cosine.exponent = 3.0f;
    const std::vector<float> a = project(test::shared_context(), RC_BASIS_SH, cosine, 99u);
    ContextOptions options = test::default_context_options();
    options.local_size = 1;
    Context other(options);
    const std::vector<float> b = project(other, RC_BASIS_SH, cosine, 99u);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i], b[i]) << i;
    }
    const std::vector<float> c = project(test::shared_context(), RC_BASIS_SH, cosine, 100u);
    EXPECT_NE(a, c) << "the key does not change the jitter";
}

}  // namespace
}  // namespace rc
