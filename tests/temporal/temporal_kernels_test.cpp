// Temporal caching's device functions against independent oracles: the unshadowed irradiance of
// every emitter kind (kernels/temporal/tc_unshadowed.h) against Monte Carlo integration over the
// emitting triangle and closed forms; the cell a direction passes through
// (kernels/temporal/tc_reprojection.h) against the definition of the stratified cells.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "shared/temporal.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;
using glm::dvec3;

shared::float4 f4(dvec3 v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0.0f};
}

shared::TcEmitter area_triangle(dvec3 a, dvec3 b, dvec3 c, float radiance) {
    shared::TcEmitter e{};
    e.light.kind = RC_LIGHT_AREA;
    e.light.radiance = {radiance, 2.0f * radiance, 0.5f * radiance, 0.0f};
    e.v0 = f4(a);
    e.v1 = f4(b);
    e.v2 = f4(c);
    return e;
}

// Irradiance at p (normal n) from a triangle of radiance 1 emitting on its winding's side, by
// uniform area sampling: E = integral of cos_p cos_l / r^2 dA (double precision).
double monte_carlo_triangle(dvec3 a, dvec3 b, dvec3 c, dvec3 p, dvec3 n, int samples) {
    const dvec3 winding = glm::cross(b - a, c - a);
    const double area = 0.5 * glm::length(winding);
    const dvec3 nl = glm::normalize(winding);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const double su = std::sqrt(u(rng));
        const double v = u(rng);
        const dvec3 q = (1.0 - su) * a + su * (1.0 - v) * b + su * v * c;
        const dvec3 d = q - p;
        const double r2 = glm::dot(d, d);
        const dvec3 w = d / std::sqrt(r2);
        const double cos_p = glm::dot(n, w);
        const double cos_l = -glm::dot(nl, w);
        if (cos_p > 0.0 && cos_l > 0.0) {
            sum += cos_p * cos_l / r2;
        }
    }
    return sum * area / samples;
}

// The probe's irradiance at each (point, normal) pair from `emitters`.
std::vector<shared::float4> unshadowed(const std::vector<shared::TcEmitter>& emitters,
                                       const std::vector<dvec3>& points_and_normals) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("temporal/tc_probe.cl", "tc_unshadowed_probe");
    std::vector<shared::float4> queries;
    for (const dvec3& v : points_and_normals) {
        queries.push_back(f4(v));
    }
    const Buffer<shared::TcEmitter> emitter_buffer(context, emitters, "emitters");
    const Buffer<shared::float4> query_buffer(context, queries, "queries");
    Buffer<shared::float4> out(context, queries.size() / 2, "out");
    context.launch(kernel, queries.size() / 2, emitter_buffer, static_cast<int>(emitters.size()),
                   query_buffer, out);
    return out.download();
}

// Lambert's polygon formula for a triangle against Monte Carlo over the triangle, at points
// that see it whole above their horizon, at every orientation of the triangle's corners; zero
// behind the emitting side; radiance scales the result per channel.
TEST(TemporalKernels, TriangleIrradianceMatchesMonteCarlo) {
    const dvec3 a(-0.4, 1.0, -0.3);
    const dvec3 b(0.5, 1.1, -0.2);
    const dvec3 c(0.1, 0.9, 0.6);
    const bool faces_down = glm::cross(b - a, c - a).y < 0.0;
    // Emitting downwards whatever the corners' order.
    const dvec3 b_down = faces_down ? b : c;
    const dvec3 c_down = faces_down ? c : b;
    struct Query {
        dvec3 p;
        dvec3 n;
    };
    const std::vector<Query> queries = {
        {{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}},
        {{0.7, -0.2, 0.3}, glm::normalize(dvec3(-0.3, 1.0, 0.1))},
        {{-0.5, 0.3, -0.6}, glm::normalize(dvec3(0.4, 0.8, 0.5))},
        {{0.1, 0.5, 0.0}, glm::normalize(dvec3(0.0, 1.0, -0.2))},
    };
    std::vector<double> expected;
    for (const Query& q : queries) {
        expected.push_back(monte_carlo_triangle(a, b_down, c_down, q.p, q.n, 2000000));
    }
    for (int order = 0; order < 3; ++order) {
        // The same triangle with its corners rotated: the formula's sign must not depend on it.
        const dvec3 corners[3] = {a, b_down, c_down};
        const shared::TcEmitter e =
            area_triangle(corners[order], corners[(order + 1) % 3], corners[(order + 2) % 3], 1.0f);
        std::vector<dvec3> pn;
        for (const Query& q : queries) {
            pn.push_back(q.p);
            pn.push_back(q.n);
        }
        const std::vector<shared::float4> device = unshadowed({e}, pn);
        for (size_t i = 0; i < queries.size(); ++i) {
            EXPECT_NEAR(device[i].x, expected[i], 0.005 * expected[i]) << "query " << i;
            EXPECT_NEAR(device[i].y, 2.0 * expected[i], 0.01 * expected[i]) << "query " << i;
        }
    }
    // From above, the emitting side faces away: nothing.
    const shared::TcEmitter e = area_triangle(a, b_down, c_down, 1.0f);
    const std::vector<shared::float4> behind = unshadowed({e}, {{0.0, 3.0, 0.0}, {0.0, -1.0, 0.0}});
    EXPECT_EQ(behind[0].x, 0.0f);
}

// A large square split in two triangles just above a point approaches the whole hemisphere: E ->
// pi.
TEST(TemporalKernels, LargeEmitterOverheadGivesPi) {
    const double s = 1000.0;
    const dvec3 v00(-s, 1.0, -s), v10(s, 1.0, -s), v11(s, 1.0, s), v01(-s, 1.0, s);
    // Winding facing down (-y): (v10 - v00) x (v01 - v00) is -y... choose the order that does.
    const bool down = glm::cross(v10 - v00, v11 - v00).y < 0.0;
    std::vector<shared::TcEmitter> emitters;
    if (down) {
        emitters = {area_triangle(v00, v10, v11, 1.0f), area_triangle(v00, v11, v01, 1.0f)};
    } else {
        emitters = {area_triangle(v00, v11, v10, 1.0f), area_triangle(v00, v01, v11, 1.0f)};
    }
    const std::vector<shared::float4> e = unshadowed(emitters, {{0, 0, 0}, {0, 1, 0}});
    EXPECT_NEAR(e[0].x, kPi, 0.01);
}

// Point, spot and environment lights by their closed forms: I cos / r^2, the spot's falloff (1
// inside the beam, 0 past the cutoff), pi L; several emitters add.
TEST(TemporalKernels, PointSpotAndEnvironmentFollowTheirClosedForms) {
    shared::TcEmitter point{};
    point.light.kind = RC_LIGHT_POINT;
    point.light.position = {0.0f, 2.0f, 0.0f, 0.0f};
    point.light.radiance = {4.0f, 4.0f, 4.0f, 0.0f};
    shared::TcEmitter spot = point;
    spot.light.kind = RC_LIGHT_SPOT;
    spot.light.axis = {0.0f, -1.0f, 0.0f, 0.0f};
    spot.light.beam = 0.3f;
    spot.light.cutoff = 0.5f;
    spot.light.cos_beam = std::cos(0.3f);
    spot.light.cos_cutoff = std::cos(0.5f);
    shared::TcEmitter sky{};
    sky.light.kind = RC_LIGHT_CONSTANT;
    sky.light.radiance = {0.5f, 0.25f, 1.0f, 0.0f};
    const dvec3 p(0.3, 0.0, 0.1);
    const dvec3 n = glm::normalize(dvec3(0.2, 1.0, 0.0));
    const dvec3 to_light = dvec3(0.0, 2.0, 0.0) - p;
    const double r2 = glm::dot(to_light, to_light);
    const double closed = 4.0 * glm::dot(n, glm::normalize(to_light)) / r2;
    const std::vector<shared::float4> e =
        unshadowed({point, spot, sky}, {p, n, {3.0, 0.0, 0.0}, {0.0, 1.0, 0.0}});
    // Inside the spot's beam (angle 0.16 rad): both lights in full, and the sky.
    EXPECT_NEAR(e[0].x, 2.0 * closed + kPi * 0.5, 1e-4);
    EXPECT_NEAR(e[0].z, 2.0 * closed + kPi * 1.0, 1e-4);
    // At (3, 0, 0) the spot's angle is 0.98 rad, past its cutoff: the point light and the sky.
    const dvec3 far_light = dvec3(0.0, 2.0, 0.0) - dvec3(3.0, 0.0, 0.0);
    const double far = 4.0 * glm::normalize(far_light).y / glm::dot(far_light, far_light);
    EXPECT_NEAR(e[1].x, far + kPi * 0.5, 1e-4);
}

// A distant light by its closed form: E max(0, cos) between the normal and the direction to it;
// nothing on a surface facing away.
TEST(TemporalKernels, DistantLightGivesIrradianceTimesCosine) {
    shared::TcEmitter sun{};
    sun.light.kind = RC_LIGHT_DISTANT;
    const dvec3 travel = glm::normalize(dvec3(0.6, -0.8, 0.0));
    sun.light.axis = f4(travel);
    sun.light.radiance = {3.0f, 2.0f, 1.0f, 0.0f};
    const dvec3 n = glm::normalize(dvec3(0.2, 1.0, 0.3));
    const std::vector<shared::float4> e =
        unshadowed({sun}, {{5.0, 1.0, -2.0}, n, {0.0, 0.0, 0.0}, -n});
    const double cosine = glm::dot(n, -travel);
    EXPECT_NEAR(e[0].x, 3.0 * cosine, 1e-5);
    EXPECT_NEAR(e[0].z, 1.0 * cosine, 1e-5);
    EXPECT_EQ(e[1].x, 0.0f);
    EXPECT_EQ(e[1].y, 0.0f);
}

// The cell a direction passes through holds it: column k with 2 pi k / N <= phi < 2 pi (k+1)/N
// and, for irradiance records' cosine-weighted cells (irradiance_records.h), row j with
// j/M <= sin^2 theta < (j+1)/M; for radiance records' uniform cells (radiance_hemisphere.h)
// j/M <= 1 - cos theta < (j+1)/M; -1 below.
void check_cell_of_direction(int layout) {
    const int m = 18;
    const int n = 57;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<shared::float4> directions;
    for (int i = 0; i < 20000; ++i) {
        const double z = i % 100 == 0 ? -u(rng) : u(rng);  // some below the hemisphere
        const double phi = 2.0 * kPi * u(rng);
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        directions.push_back(f4(dvec3(s * std::cos(phi), s * std::sin(phi), z)));
    }
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("temporal/tc_probe.cl", "tc_cell_probe");
    const Buffer<shared::float4> in(context, directions, "directions");
    Buffer<int> out(context, directions.size(), "cells");
    context.launch(kernel, directions.size(), m, n, layout, in, out);
    const std::vector<int> cells = out.download();
    int checked = 0;
    for (size_t i = 0; i < directions.size(); ++i) {
        const dvec3 d(directions[i].x, directions[i].y, directions[i].z);  // as the device saw it
        if (!(d.z > 0.0)) {
            EXPECT_EQ(cells[i], -1);
            continue;
        }
        const double row = layout == RC_TC_CELLS_UNIFORM ? 1.0 - d.z : 1.0 - d.z * d.z;
        double phi = std::atan2(d.y, d.x);
        phi += phi < 0.0 ? 2.0 * kPi : 0.0;
        const int j = cells[i] / n;
        const int k = cells[i] % n;
        // float rounding of the direction: allow 1e-5 across a stratum's border.
        EXPECT_GE(row, static_cast<double>(j) / m - 1e-5) << i;
        EXPECT_LT(row, static_cast<double>(j + 1) / m + 1e-5) << i;
        EXPECT_GE(phi, 2.0 * kPi * k / n - 1e-5) << i;
        EXPECT_LT(phi, 2.0 * kPi * (k + 1) / n + 1e-5) << i;
        ++checked;
    }
    EXPECT_GT(checked, 19000);
}

TEST(TemporalKernels, CellOfADirectionIsTheStratumHoldingIt) {
    check_cell_of_direction(RC_TC_CELLS_COSINE);
}

TEST(TemporalKernels, CellOfADirectionIsTheUniformStratumHoldingIt) {
    check_cell_of_direction(RC_TC_CELLS_UNIFORM);
}

}  // namespace
}  // namespace rc
