// Exact rotation of spherical-harmonic coefficient vectors on the device
// (kernels/shared/sh_rotation.h): rotate-then-evaluate equals evaluate-in-the-rotated-direction
// at random directions, rotations and orders; composition, inverse and norm; the closed form of
// rotations about z; and the frame-to-frame rotation (kernels/radiance_cache/rc_rotation.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sh_quadrature.h"
#include "shared/sh_rotation_zxz.h"
#include "shared/spherical_harmonics.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr int kVectors = 3;  // r, g, b

std::vector<double> multiply(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> c(9, 0.0);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            for (int k = 0; k < 3; ++k) {
                c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
            }
        }
    }
    return c;
}

std::vector<double> transpose(const std::vector<double>& a) {
    return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}

// The rows of every rotation (row-major 3x3), three float4s each, as the probe kernels read them.
std::vector<shared::float4> rotation_rows(const std::vector<std::vector<double>>& rotations) {
    std::vector<shared::float4> rows;
    for (const std::vector<double>& r : rotations) {
        for (int row = 0; row < 3; ++row) {
            rows.push_back({static_cast<float>(r[3 * row]), static_cast<float>(r[3 * row + 1]),
                            static_cast<float>(r[3 * row + 2]), 0.0f});
        }
    }
    return rows;
}

// Rotates items of kVectors vectors of `order` on the device: item i by rotations[i].
std::vector<float> rotate(int order, const std::vector<std::vector<double>>& rotations,
                          const std::vector<float>& coefficients) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_rotation_probe");
    const Buffer<shared::float4> device_rows(context, rotation_rows(rotations), "rotations");
    Buffer<float> c(context, coefficients, "coefficients");
    context.launch(kernel, rotations.size(), order, kVectors, device_rows, c);
    return c.download();
}

// As rotate, by the zxzxz factorization (rc_rotation_zxz_probe) with the host-built table.
std::vector<float> rotate_zxz(int order, const std::vector<std::vector<double>>& rotations,
                              const std::vector<float>& coefficients) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_rotation_zxz_probe");
    std::vector<float> table(RC_SH_X90_TABLE_SIZE);
    shared::rc_sh_x90_table(table.data());
    const Buffer<shared::float4> device_rows(context, rotation_rows(rotations), "rotations");
    const Buffer<float> x90(context, table, "x90");
    Buffer<float> c(context, coefficients, "coefficients");
    context.launch(kernel, rotations.size(), order, kVectors, device_rows, x90, c);
    return c.download();
}

std::vector<float> random_coefficients(std::mt19937& rng, size_t count) {
    std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
    std::vector<float> c(count);
    for (float& v : c) {
        v = uniform(rng);
    }
    return c;
}

double evaluate(const float* c, int order, double x, double y, double z) {
    float basis[RC_SH_MAX_COEFFICIENTS];
    shared::rc_sh_eval(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z), order,
                       basis);
    double sum = 0.0;
    for (int i = 0; i < order * order; ++i) {
        sum += static_cast<double>(c[i]) * basis[i];
    }
    return sum;
}

double norm(const float* c, int count) {
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        sum += static_cast<double>(c[i]) * c[i];
    }
    return std::sqrt(sum);
}

// sum c'_i Y_i(R d) = sum c_i Y_i(d), to 1e-4 of the largest value a vector of that norm can take
// (|f(d)| <= |c| n / sqrt(4 pi) by Cauchy-Schwarz and the addition theorem).
TEST(ShRotation, RotateThenEvaluateEqualsEvaluateInTheRotatedDirection) {
    std::mt19937 rng(5);
    for (int order = 1; order <= RC_SH_MAX_ORDER; ++order) {
        const int count = order * order;
        const int items = 32;
        std::vector<std::vector<double>> rotations;
        for (int i = 0; i < items; ++i) {
            rotations.push_back(test::random_rotation(rng));
        }
        const std::vector<float> c = random_coefficients(rng, items * kVectors * count);
        const std::vector<float> rotated = rotate(order, rotations, c);
        for (int i = 0; i < items; ++i) {
            const std::vector<double>& r = rotations[i];
            for (int sample = 0; sample < 8; ++sample) {
                const shared::float4 d = test::random_direction(rng);
                const double rx = r[0] * d.x + r[1] * d.y + r[2] * d.z;
                const double ry = r[3] * d.x + r[4] * d.y + r[5] * d.z;
                const double rz = r[6] * d.x + r[7] * d.y + r[8] * d.z;
                for (int v = 0; v < kVectors; ++v) {
                    const float* before = &c[(i * kVectors + v) * count];
                    const float* after = &rotated[(i * kVectors + v) * count];
                    const double scale =
                        norm(before, count) * order / std::sqrt(4 * std::numbers::pi);
                    EXPECT_NEAR(evaluate(after, order, rx, ry, rz),
                                evaluate(before, order, d.x, d.y, d.z), 1e-4 * scale)
                        << "order " << order << " item " << i << " vector " << v;
                }
            }
        }
    }
}

// D(R2) D(R1) = D(R2 R1), D(R^T) D(R) = 1, and |D c| = |c|.
TEST(ShRotation, ComposesInvertsAndPreservesTheNorm) {
    std::mt19937 rng(8);
    const int order = RC_SH_MAX_ORDER;
    const int count = order * order;
    const int items = 64;
    std::vector<std::vector<double>> first, second, product, inverse;
    for (int i = 0; i < items; ++i) {
        first.push_back(test::random_rotation(rng));
        second.push_back(test::random_rotation(rng));
        product.push_back(multiply(second.back(), first.back()));
        inverse.push_back(transpose(first.back()));
    }
    const std::vector<float> c = random_coefficients(rng, items * kVectors * count);
    const std::vector<float> once = rotate(order, first, c);
    const std::vector<float> twice = rotate(order, second, once);
    const std::vector<float> composed = rotate(order, product, c);
    const std::vector<float> back = rotate(order, inverse, once);
    for (int v = 0; v < items * kVectors; ++v) {
        const float* original = &c[v * count];
        const double scale = norm(original, count);
        EXPECT_NEAR(norm(&once[v * count], count), scale, 1e-5 * scale);
        for (int i = 0; i < count; ++i) {
            EXPECT_NEAR(twice[v * count + i], composed[v * count + i], 1e-4 * scale);
            EXPECT_NEAR(back[v * count + i], original[i], 1e-4 * scale);
        }
    }
}

// About z by alpha, band l mixes only (m, -m): c'_m = c_m cos(m alpha) - c_-m sin(m alpha),
// c'_-m = c_m sin(m alpha) + c_-m cos(m alpha) (the azimuth grows by alpha).
TEST(ShRotation, RotationAboutZMatchesItsClosedForm) {
    std::mt19937 rng(13);
    const int order = RC_SH_MAX_ORDER;
    const int count = order * order;
    std::vector<std::vector<double>> rotations;
    std::vector<double> angles;
    for (double alpha : {0.0, 0.3, 1.0, 2.5, -2.0}) {
        angles.push_back(alpha);
        rotations.push_back(
            {std::cos(alpha), -std::sin(alpha), 0, std::sin(alpha), std::cos(alpha), 0, 0, 0, 1});
    }
    const std::vector<float> c = random_coefficients(rng, rotations.size() * kVectors * count);
    const std::vector<float> rotated = rotate(order, rotations, c);
    for (size_t item = 0; item < rotations.size(); ++item) {
        for (int v = 0; v < kVectors; ++v) {
            const size_t at = (item * kVectors + v) * count;
            for (int l = 0; l < order; ++l) {
                EXPECT_NEAR(rotated[at + shared::rc_sh_index(l, 0)],
                            c[at + shared::rc_sh_index(l, 0)], 1e-5);
                for (int m = 1; m <= l; ++m) {
                    const double cm = c[at + shared::rc_sh_index(l, m)];
                    const double cn = c[at + shared::rc_sh_index(l, -m)];
                    const double a = m * angles[item];
                    EXPECT_NEAR(rotated[at + shared::rc_sh_index(l, m)],
                                cm * std::cos(a) - cn * std::sin(a), 2e-5);
                    EXPECT_NEAR(rotated[at + shared::rc_sh_index(l, -m)],
                                cm * std::sin(a) + cn * std::cos(a), 2e-5);
                }
            }
        }
    }
}

// Rotations where the ZYZ angles degenerate or are special, then random ones: identity, about z,
// Rx(+-90), Rx(180) (beta = pi), tilts of 1e-4 and 1e-7 rad (sin beta near the cut-off).
std::vector<std::vector<double>> zxz_rotations(std::mt19937& rng) {
    std::vector<std::vector<double>> rotations = {{1, 0, 0, 0, 1, 0, 0, 0, 1},
                                                  {0, -1, 0, 1, 0, 0, 0, 0, 1},
                                                  {1, 0, 0, 0, 0, -1, 0, 1, 0},
                                                  {1, 0, 0, 0, 0, 1, 0, -1, 0},
                                                  {1, 0, 0, 0, -1, 0, 0, 0, -1}};
    for (double tilt : {1e-4, 1e-7}) {
        const double c = std::cos(tilt), s = std::sin(tilt);
        const std::vector<double> tilt_x = {1, 0, 0, 0, c, -s, 0, s, c};
        rotations.push_back(multiply(test::random_rotation(rng), tilt_x));
        const std::vector<double> z = {0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1};
        rotations.push_back(multiply(z, tilt_x));
    }
    for (int i = 0; i < 32; ++i) {
        rotations.push_back(test::random_rotation(rng));
    }
    return rotations;
}

// The zxzxz factorization satisfies the defining property itself (rotate-then-evaluate =
// evaluate at the rotated direction) and agrees with the Ivanic-Ruedenberg rotation, at every
// order, to 1e-4 of the vector's scale.
TEST(ShRotation, ZxzFactorizationMatchesTheExactRotation) {
    std::mt19937 rng(34);
    for (int order = 1; order <= RC_SH_MAX_ORDER; ++order) {
        const int count = order * order;
        const std::vector<std::vector<double>> rotations = zxz_rotations(rng);
        const int items = static_cast<int>(rotations.size());
        const std::vector<float> c = random_coefficients(rng, items * kVectors * count);
        const std::vector<float> fast = rotate_zxz(order, rotations, c);
        const std::vector<float> exact = rotate(order, rotations, c);
        for (int i = 0; i < items; ++i) {
            const std::vector<double>& r = rotations[i];
            for (int v = 0; v < kVectors; ++v) {
                const size_t at = static_cast<size_t>(i * kVectors + v) * count;
                const double scale = norm(&c[at], count);
                for (int k = 0; k < count; ++k) {
                    EXPECT_NEAR(fast[at + k], exact[at + k], 1e-4 * scale)
                        << "order " << order << " item " << i << " coefficient " << k;
                }
                const shared::float4 d = test::random_direction(rng);
                const double rx = r[0] * d.x + r[1] * d.y + r[2] * d.z;
                const double ry = r[3] * d.x + r[4] * d.y + r[5] * d.z;
                const double rz = r[6] * d.x + r[7] * d.y + r[8] * d.z;
                EXPECT_NEAR(evaluate(&fast[at], order, rx, ry, rz),
                            evaluate(&c[at], order, d.x, d.y, d.z),
                            1e-4 * scale * order / std::sqrt(4 * std::numbers::pi))
                    << "order " << order << " item " << i;
            }
        }
    }
}

// The table is D(Rx +90): orthogonal per band (D D^T = 1).
TEST(ShRotation, X90TableIsOrthogonal) {
    std::vector<float> table(RC_SH_X90_TABLE_SIZE);
    shared::rc_sh_x90_table(table.data());
    for (int l = 0; l < RC_SH_MAX_ORDER; ++l) {
        const int size = 2 * l + 1;
        const float* band = &table[shared::rc_sh_x90_band_offset(l)];
        for (int a = 0; a < size; ++a) {
            for (int b = 0; b < size; ++b) {
                double sum = 0.0;
                for (int k = 0; k < size; ++k) {
                    sum += static_cast<double>(band[a * size + k]) * band[b * size + k];
                }
                EXPECT_NEAR(sum, a == b ? 1.0 : 0.0, 1e-5) << "band " << l;
            }
        }
    }
}

// rc_frame_rotation maps a world direction's coordinates in one frame to those in the other.
TEST(ShRotation, FrameRotationMapsLocalCoordinates) {
    std::mt19937 rng(21);
    const int items = 16;
    std::vector<shared::float4> from, to;
    std::vector<std::vector<double>> from_axes, to_axes;
    for (int i = 0; i < items; ++i) {
        for (auto* frames : {&from_axes, &to_axes}) {
            const std::vector<double> r = test::random_rotation(rng);
            frames->push_back(r);  // rows: t, b, n
            auto& out = frames == &from_axes ? from : to;
            for (int row = 0; row < 3; ++row) {
                out.push_back({static_cast<float>(r[3 * row]), static_cast<float>(r[3 * row + 1]),
                               static_cast<float>(r[3 * row + 2]), 0.0f});
            }
        }
    }
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_frame_rotation_probe");
    const Buffer<shared::float4> a(context, from, "from");
    const Buffer<shared::float4> b(context, to, "to");
    Buffer<shared::float4> out(context, 3 * items, "rotation");
    context.launch(kernel, items, a, b, out);
    const std::vector<shared::float4> r = out.download();
    for (int i = 0; i < items; ++i) {
        const shared::float4 w = test::random_direction(rng);
        double local_from[3], local_to[3];
        for (int axis = 0; axis < 3; ++axis) {
            const double* f = &from_axes[i][3 * axis];
            const double* t = &to_axes[i][3 * axis];
            local_from[axis] = f[0] * w.x + f[1] * w.y + f[2] * w.z;
            local_to[axis] = t[0] * w.x + t[1] * w.y + t[2] * w.z;
        }
        for (int row = 0; row < 3; ++row) {
            const shared::float4& rr = r[3 * i + row];
            EXPECT_NEAR(rr.x * local_from[0] + rr.y * local_from[1] + rr.z * local_from[2],
                        local_to[row], 1e-5);
        }
    }
}

}  // namespace
}  // namespace rc
