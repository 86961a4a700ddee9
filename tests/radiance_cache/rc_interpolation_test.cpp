// A record's reflection at a query point (kernels/radiance_cache/rc_interpolation.h) in the
// "white sky": records projected (with gradients) from a constant sky and no occluders, read at a
// displaced query whose frame differs from the record's, reflect L albedo(w_o), with the albedo
// integrated on the host from the material's own BRDF evaluation (kernels/material_probe.cl).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "methods/radiance_cache/brdf_tables.h"
#include "sh_quadrature.h"
#include "shared/sh_rotation_zxz.h"
#include "shared/spherical_harmonics.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr int kOrder = RC_SH_MAX_ORDER;
constexpr int kCount = kOrder * kOrder;
constexpr int kStrataM = 32;
constexpr int kStrataN = 128;
constexpr int kQueries = 16;
const shared::float4 kSky = {1.0f, 0.5f, 0.25f, 0.0f};

// Records (9 kCount floats: coefficients, gradients) of the constant sky: every cell brings kSky
// from infinitely far; record q draws the directions of stream q.
std::vector<float> sky_records(Context& context) {
    Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_gradient_probe");
    const shared::float4 cell = {kSky.x, kSky.y, kSky.z, std::numeric_limits<float>::infinity()};
    std::vector<float> records;
    for (unsigned q = 0; q < kQueries; ++q) {
        const Buffer<shared::float4> cells(
            context, std::vector<shared::float4>(kStrataM * kStrataN, cell), "cells");
        Buffer<float> out(context, 9 * kCount, "record");
        context.launch(kernel, 1, kStrataM, kStrataN, 3u, 4u, q, RC_BASIS_SH, kOrder, cells, out);
        const std::vector<float> r = out.download();
        records.insert(records.end(), r.begin(), r.end());
    }
    return records;
}

// Query frames reached from the record's by a rotation about the normal (frames on a flat
// surface: the record's hemisphere is the query's, so the white sky is exact up to the SH
// representation) or by a tilt of 15 degrees about a random horizontal axis (a curved surface: the
// record's hemisphere, rotated, is what the query reflects). Bounds: 3% about the normal (the
// table's 2% and the stratified projection), 6% tilted (the SH series of the record's horizon).
TEST(RcInterpolation, WhiteSkyReflectsRadianceTimesAlbedo) {
    Context& context = test::shared_context();
    const Material material = test::pure_phong(8.0f);
    BrdfTableOptions options;
    options.theta_nodes = 32;
    options.phi_nodes = 64;
    const BrdfTables tables(context, {material}, options);
    std::vector<float> table(RC_SH_X90_TABLE_SIZE);
    shared::rc_sh_x90_table(table.data());
    const Buffer<float> x90(context, table, "x90");
    const Buffer<float> records(context, sky_records(context), "records");
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (bool tilted : {false, true}) {
        std::vector<std::vector<double>> rotations;
        std::vector<shared::float4> rows, displacements, wo;
        for (int q = 0; q < kQueries; ++q) {
            const double a = 2.0 * std::numbers::pi * uniform(rng);
            std::vector<double> r = {
                std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1};
            if (tilted) {
                const double t = 15.0 * std::numbers::pi / 180.0,
                             b = 2.0 * std::numbers::pi * uniform(rng);
                // Rodrigues' rotation by t about the horizontal axis (cos b, sin b, 0).
                const double kx = std::cos(b), ky = std::sin(b), c = std::cos(t), s = std::sin(t);
                const std::vector<double> tilt = {c + kx * kx * (1 - c),
                                                  kx * ky * (1 - c),
                                                  ky * s,
                                                  kx * ky * (1 - c),
                                                  c + ky * ky * (1 - c),
                                                  -kx * s,
                                                  -ky * s,
                                                  kx * s,
                                                  c};
                std::vector<double> product(9, 0.0);
                for (int i = 0; i < 3; ++i) {
                    for (int j = 0; j < 3; ++j) {
                        for (int k = 0; k < 3; ++k) {
                            product[3 * i + j] += tilt[3 * i + k] * r[3 * k + j];
                        }
                    }
                }
                r = product;
            }
            rotations.push_back(r);
            for (int row = 0; row < 3; ++row) {
                rows.push_back({static_cast<float>(r[3 * row]), static_cast<float>(r[3 * row + 1]),
                                static_cast<float>(r[3 * row + 2]), 0.0f});
            }
            displacements.push_back({static_cast<float>(uniform(rng) - 0.5),
                                     static_cast<float>(uniform(rng) - 0.5), 0.0f, 0.0f});
            const double theta = std::acos(1.0 - uniform(rng) * (1.0 - std::cos(1.3)));
            const double phi = 2.0 * std::numbers::pi * uniform(rng);
            wo.push_back({static_cast<float>(std::sin(theta) * std::cos(phi)),
                          static_cast<float>(std::sin(theta) * std::sin(phi)),
                          static_cast<float>(std::cos(theta)), 0.0f});
        }
        Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_reflection_probe");
        const Buffer<shared::float4> device_rows(context, rows, "rotations");
        const Buffer<shared::float4> device_displacements(context, displacements, "displacements");
        const Buffer<shared::float4> device_wo(context, wo, "wo");
        Buffer<shared::float4> out(context, kQueries, "reflected");
        context.launch(kernel, kQueries, kOrder, tables.infos()[0], tables.coefficients(), x90,
                       records, device_displacements, device_rows, device_wo, out);
        const std::vector<shared::float4> reflected = out.download();
        const double bound = tilted ? 0.06 : 0.03;
        double worst = 0.0;
        for (int q = 0; q < kQueries; ++q) {
            const double a = test::record_hemisphere_albedo(context, material, wo[q], rotations[q]);
            const double channels[3] = {reflected[q].x, reflected[q].y, reflected[q].z};
            const double sky[3] = {kSky.x, kSky.y, kSky.z};
            for (int c = 0; c < 3; ++c) {
                const double expected = sky[c] * a;
                worst = std::max(worst, std::abs(channels[c] - expected) / expected);
                EXPECT_NEAR(channels[c], expected, bound * expected)
                    << (tilted ? "tilted" : "flat") << " query " << q << " channel " << c;
            }
        }
        std::printf("%s frames: largest relative error %.4f\n", tilted ? "tilted" : "flat", worst);
    }
}

}  // namespace
}  // namespace rc
