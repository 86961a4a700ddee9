// Translational gradients of radiance records (kernels/radiance_cache/rc_gradients.h) against
// central finite differences of records displaced in an analytic scene: a record under the
// ceiling z = 1 that emits a Gaussian spot, whose coefficients at p +- delta x and p +- delta y
// are projected from the same stratified directions (common random numbers), so the difference
// quotient is the derivative of the very estimate the gradient approximates.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/spherical_harmonics.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr int kOrder = 6;
constexpr int kCount = kOrder * kOrder;
constexpr int kStrataM = 32;
constexpr int kStrataN = 128;
constexpr float kSpot = 1.0f;
constexpr float kDelta = 0.01f;
const shared::float4 kColour = {1.0f, 0.5f, 0.25f, 0.0f};

// Coefficients and gradients (9 kCount floats each) of records at `positions` (w: the ceiling's
// height), all drawing the directions of `stream`.
std::vector<float> project(const std::vector<shared::float4>& positions, unsigned stream) {
    Context& context = test::shared_context();
    Kernel cells_kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_ceiling_cells_probe");
    Kernel gradient_kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_gradient_probe");
    const size_t records = positions.size();
    const Buffer<shared::float4> device_positions(context, positions, "positions");
    Buffer<shared::float4> cells(context, records * kStrataM * kStrataN, "cells");
    context.launch(cells_kernel, records * kStrataM * kStrataN, kStrataM, kStrataN, 7u, 9u, stream,
                   kSpot, kColour, device_positions, cells);
    Buffer<float> out(context, records * 9 * kCount, "coefficients");
    context.launch(gradient_kernel, records, kStrataM, kStrataN, 7u, 9u, stream, RC_BASIS_SH,
                   kOrder, cells, out);
    return out.download();
}

// For two record positions and four streams, every channel's x and y gradient vectors against
// the central differences of the coefficient vectors: relative L2 error over bands 0-2 below
// kLowBound, over all kOrder bands below kAllBound. The wall-movement estimate differences
// neighbouring cells, so its error grows with the basis functions' frequency (measured: at most
// 0.068 over bands 0-2, 0.159 over all 6 bands, 32 x 128 cells).
constexpr double kLowBound = 0.10;
constexpr double kAllBound = 0.25;

TEST(RcGradient, MatchesFiniteDifferencesOfDisplacedRecords) {
    const shared::float4 centres[] = {{0.3f, -0.2f, 0.0f, 1.0f}, {-0.8f, 0.5f, 0.0f, 0.7f}};
    double worst_low = 0.0, worst_all = 0.0;
    for (const shared::float4& p : centres) {
        std::vector<shared::float4> positions = {p, p, p, p, p};
        positions[1].x += kDelta;
        positions[2].x -= kDelta;
        positions[3].y += kDelta;
        positions[4].y -= kDelta;
        for (unsigned stream = 0; stream < 4; ++stream) {
            const std::vector<float> r = project(positions, stream);
            for (int channel = 0; channel < 3; ++channel) {
                for (int axis = 0; axis < 2; ++axis) {
                    const int plus = 1 + 2 * axis;
                    // Relative L2 errors over bands 0-2 (the first 9) and over all bands.
                    double errors[2] = {0.0, 0.0}, norms[2] = {0.0, 0.0};
                    for (int i = 0; i < kCount; ++i) {
                        const double difference =
                            (r[plus * 9 * kCount + channel * kCount + i] -
                             r[(plus + 1) * 9 * kCount + channel * kCount + i]) /
                            (2.0 * kDelta);
                        const double gradient = r[3 * kCount + (2 * channel + axis) * kCount + i];
                        for (int part = 0; part < 2; ++part) {
                            if (part == 1 || i < 9) {
                                errors[part] += (gradient - difference) * (gradient - difference);
                                norms[part] += difference * difference;
                            }
                        }
                    }
                    const double low = std::sqrt(errors[0] / norms[0]);
                    const double all = std::sqrt(errors[1] / norms[1]);
                    worst_low = std::max(worst_low, low);
                    worst_all = std::max(worst_all, all);
                    EXPECT_LT(low, kLowBound)
                        << "stream " << stream << " channel " << channel << " axis " << axis;
                    EXPECT_LT(all, kAllBound)
                        << "stream " << stream << " channel " << channel << " axis " << axis;
                }
            }
        }
    }
    std::printf("largest relative error: bands 0-2 %.4f, all %d bands %.4f\n", worst_low, kOrder,
                worst_all);
}

}  // namespace
}  // namespace rc
