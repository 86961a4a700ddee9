// The (hemi)spherical-harmonic basis (kernels/shared/spherical_harmonics.h) on the device:
// orthonormality by host quadrature, the addition theorem, closed forms of the first bands, and
// the same values from the host build of the shared code. Also the Gauss-Legendre rule the
// quadratures use.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "methods/radiance_cache/gauss_legendre.h"
#include "sh_quadrature.h"
#include "shared/spherical_harmonics.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kOrder = RC_SH_MAX_ORDER;
constexpr int kCount = kOrder * kOrder;

TEST(GaussLegendre, IntegratesPolynomialsUpToDegree2nMinus1Exactly) {
    for (int n : {1, 2, 5, 24, 64}) {
        const QuadratureRule rule = gauss_legendre(n, 0.0, 1.0);
        double total = 0.0;
        for (double w : rule.weights) {
            total += w;
        }
        EXPECT_NEAR(total, 1.0, 1e-13) << n;
        for (int degree = 0; degree <= 2 * n - 1; degree += std::max(1, n / 3)) {
            double sum = 0.0;
            for (int j = 0; j < n; ++j) {
                sum += rule.weights[j] * std::pow(rule.nodes[j], degree);
            }
            EXPECT_NEAR(sum, 1.0 / (degree + 1), 1e-13) << "n " << n << " degree " << degree;
        }
    }
    // The 4-point rule's known nodes (Abramowitz and Stegun Table 25.4).
    const QuadratureRule four = gauss_legendre(4);
    EXPECT_NEAR(four.nodes[3], 0.8611363115940526, 1e-15);
    EXPECT_NEAR(four.weights[3], 0.3478548451374538, 1e-15);
    EXPECT_THROW(gauss_legendre(0), Error);
}

// The recurrence's constant tables hold their formulas (spherical_harmonics.h).
TEST(ShBasis, RecurrenceTablesMatchTheirFormulas) {
    double q = std::sqrt(1 / (4 * kPi));
    for (int m = 0; m < kOrder; ++m) {
        if (m > 0) {
            q *= std::sqrt((2.0 * m + 1.0) / (2.0 * m));
        }
        EXPECT_NEAR(shared::rc_sh_diagonal[m], q, 1e-7 * q) << m;
        EXPECT_NEAR(shared::rc_sh_subdiagonal[m], std::sqrt(2.0 * m + 3.0), 1e-6) << m;
        for (int l = 0; l < kOrder; ++l) {
            double a = 0.0, b = 0.0;
            if (l >= m + 2) {
                a = std::sqrt((4.0 * l * l - 1.0) / (l * l - m * m));
                b = std::sqrt(((l - 1.0) * (l - 1.0) - m * m) /
                              (4.0 * (l - 1.0) * (l - 1.0) - 1.0));
            }
            EXPECT_NEAR(shared::rc_sh_recurrence_a[l * kOrder + m], a, 1e-6) << l << ", " << m;
            EXPECT_NEAR(shared::rc_sh_recurrence_b[l * kOrder + m], b, 1e-6) << l << ", " << m;
        }
    }
}

// The Gram matrix of the device's basis under a host quadrature that is exact for products of
// two basis functions: the identity, for SH over the sphere and HSH over the hemisphere.
void expect_orthonormal(int basis, double z_min) {
    const test::DirectionQuadrature q = test::product_quadrature(z_min, 16, 32);
    const std::vector<float> y =
        test::device_basis(test::shared_context(), basis, kOrder, q.directions);
    double worst = 0.0;
    for (int a = 0; a < kCount; ++a) {
        for (int b = 0; b <= a; ++b) {
            double sum = 0.0;
            for (size_t i = 0; i < q.weights.size(); ++i) {
                sum += q.weights[i] * y[i * kCount + a] * y[i * kCount + b];
            }
            worst = std::max(worst, std::abs(sum - (a == b ? 1.0 : 0.0)));
        }
    }
    EXPECT_LT(worst, 2e-5);
}

TEST(ShBasis, SphericalHarmonicsAreOrthonormalOverTheSphere) {
    expect_orthonormal(RC_BASIS_SH, -1.0);
}

TEST(ShBasis, HemisphericalHarmonicsAreOrthonormalOverTheHemisphere) {
    expect_orthonormal(RC_BASIS_HSH, 0.0);
}

// The addition theorem: sum_m Y_l^m(a) Y_l^m(b) = (2l + 1) / (4 pi) P_l(a . b), every band.
TEST(ShBasis, BandsSatisfyTheAdditionTheorem) {
    std::mt19937 rng(7);
    std::vector<shared::float4> a, b;
    for (int i = 0; i < 200; ++i) {
        a.push_back(test::random_direction(rng));
        b.push_back(test::random_direction(rng));
    }
    a.push_back({0, 0, 1, 0});  // the poles, where the azimuth is undefined
    b.push_back({0, 0, -1, 0});
    Context& context = test::shared_context();
    const std::vector<float> ya = test::device_basis(context, RC_BASIS_SH, kOrder, a);
    const std::vector<float> yb = test::device_basis(context, RC_BASIS_SH, kOrder, b);
    for (size_t i = 0; i < a.size(); ++i) {
        const double cosine = a[i].x * b[i].x + a[i].y * b[i].y + a[i].z * b[i].z;
        for (int l = 0; l < kOrder; ++l) {
            double sum = 0.0;
            for (int m = -l; m <= l; ++m) {
                const int k = shared::rc_sh_index(l, m);
                sum += static_cast<double>(ya[i * kCount + k]) * yb[i * kCount + k];
            }
            const double expected = (2 * l + 1) / (4 * kPi) * test::legendre(l, cosine);
            EXPECT_NEAR(sum, expected, 2e-6 * (2 * l + 1)) << "direction " << i << " band " << l;
        }
    }
}

// `count` random directions (test::random_direction from an RNG seeded `seed`) folded into the
// upper hemisphere (z >= 0).
std::vector<shared::float4> upper_hemisphere_directions(unsigned seed, int count) {
    std::mt19937 rng(seed);
    std::vector<shared::float4> directions;
    for (int i = 0; i < count; ++i) {
        shared::float4 v = test::random_direction(rng);
        v.z = std::abs(v.z);
        directions.push_back(v);
    }
    return directions;
}

// Bands 0-2 in Cartesian form (real SH without the Condon-Shortley phase), and the first HSH
// functions straight from the HSH paper's eq. 8 and 9.
TEST(ShBasis, FirstBandsMatchTheirClosedForms) {
    const std::vector<shared::float4> d = upper_hemisphere_directions(11, 64);
    Context& context = test::shared_context();
    const std::vector<float> y = test::device_basis(context, RC_BASIS_SH, 3, d);
    const std::vector<float> h = test::device_basis(context, RC_BASIS_HSH, 2, d);
    for (size_t i = 0; i < d.size(); ++i) {
        const double x = d[i].x, yy = d[i].y, z = d[i].z;
        const double sh[9] = {0.5 * std::sqrt(1 / kPi),
                              std::sqrt(3 / (4 * kPi)) * yy,
                              std::sqrt(3 / (4 * kPi)) * z,
                              std::sqrt(3 / (4 * kPi)) * x,
                              0.5 * std::sqrt(15 / kPi) * x * yy,
                              0.5 * std::sqrt(15 / kPi) * yy * z,
                              0.25 * std::sqrt(5 / kPi) * (3 * z * z - 1),
                              0.5 * std::sqrt(15 / kPi) * x * z,
                              0.25 * std::sqrt(15 / kPi) * (x * x - yy * yy)};
        for (int k = 0; k < 9; ++k) {
            EXPECT_NEAR(y[i * 9 + k], sh[k], 1e-6) << "Y index " << k;
        }
        // H_0^0 = K~_0^0; H_1^0 = K~_1^0 (2z - 1); H_1^{+-1} = sqrt(2) K~_1^1 {cos, sin}(phi)
        // P_1^1(2z - 1), P_1^1(t) = sqrt(1 - t^2), K~_l^m = sqrt((2l+1)(l-|m|)! / (2pi (l+|m|)!)).
        const double phi = std::atan2(yy, x);
        const double p11 = std::sqrt(1 - (2 * z - 1) * (2 * z - 1));
        const double k11 = std::sqrt(3 / (2 * kPi) / 2);
        const double hsh[4] = {std::sqrt(1 / (2 * kPi)), std::sqrt(2.0) * k11 * std::sin(phi) * p11,
                               std::sqrt(3 / (2 * kPi)) * (2 * z - 1),
                               std::sqrt(2.0) * k11 * std::cos(phi) * p11};
        for (int k = 0; k < 4; ++k) {
            EXPECT_NEAR(h[i * 4 + k], hsh[k], 1e-6) << "H index " << k;
        }
    }
}

// The shared code compiled for the host gives the device's values.
TEST(ShBasis, HostBuildAgreesWithTheDevice) {
    const std::vector<shared::float4> d = upper_hemisphere_directions(3, 100);
    for (int basis : {RC_BASIS_SH, RC_BASIS_HSH}) {
        const std::vector<float> device =
            test::device_basis(test::shared_context(), basis, kOrder, d);
        for (size_t i = 0; i < d.size(); ++i) {
            float host[kCount];
            shared::rc_basis_eval(basis, d[i].x, d[i].y, d[i].z, kOrder, host);
            for (int k = 0; k < kCount; ++k) {
                EXPECT_NEAR(host[k], device[i * kCount + k], 2e-6 * (1 + std::abs(host[k])));
            }
        }
    }
}

}  // namespace
}  // namespace rc
