// The record kernels (kernels/caching/irradiance_records.h, rc_ic_reduce) against analytic
// answers: a constant sky, and a tilted emitting rectangle whose irradiance at any point and
// orientation Lambert's polygon formula gives exactly, so finite differences of it are the oracle
// for the translational and rotational gradients.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "methods/caching/cache_pipeline.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "shared/rng.h"
#include "test_support.h"

namespace rc {
namespace {

// A scene with its device copies and an irradiance cache over it.
struct CacheFixture {
    explicit CacheFixture(const Scene& s) : device(s), cache(device.frame()) {}
    test::DeviceFrame device;
    CachePipeline cache;
};

Scene scene_from_json(const std::string& name, const std::string& json) {
    const auto dir = test::scratch_dir(name);
    std::ofstream(dir / "scene.json") << json;
    return load_scene(dir / "scene.json");
}

glm::vec3 vec3_of(const shared::float4& v) { return {v.x, v.y, v.z}; }

RecordSite site_at(glm::dvec3 position, glm::dvec3 normal) {
    RecordSite site;
    site.position = glm::vec3(position);
    site.normal = glm::vec3(glm::normalize(normal));
    site.origin = site.position + 1e-4f * site.normal;
    site.r_min = 0.0f;
    site.r_max = 1e6f;
    return site;
}

// A constant sky of radiance (1, 0.5, 0.25) over a small square far below (out of every
// hemisphere of a record near the origin facing +y).
const char* const kConstantSky = R"({
        "camera": {"position": [0, 5, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 40, "resolution": [16, 16]},
        "materials": {"ground": {"type": "diffuse", "reflectance": 0.5}},
        "shapes": [{"type": "rectangle", "material": "ground",
                    "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}},
                                  {"translate": [0, -50, 0]}]}],
        "emitters": [{"type": "constant", "radiance": [1.0, 0.5, 0.25]}]
    })";

// Under a constant sky of radiance L every hemisphere ray sees L: E = pi L, and neither gradient
// has anything to measure. (The scene's only geometry, a small square far below, is out of every
// record's hemisphere.)
TEST(IcRecord, ConstantSkyGivesPiLAndNoGradients) {
    CacheFixture f(scene_from_json("ic_sky", kConstantSky));
    RecordSampling sampling = strata_for(512);
    sampling.include_emission = true;
    sampling.seed = 3;
    const std::vector<RecordSite> sites = {site_at({0, 0, 0}, {0, 1, 0}),
                                           site_at({3, 0, -2}, {0, 1, 0}),
                                           site_at({0, 1, 0}, {0.3, 1, 0.2})};
    const std::vector<ComputedRecord> records = f.cache.compute_records(sites, 0, sampling);
    ASSERT_EQ(records.size(), sites.size());
    const double pi = 3.14159265358979;
    const double radiance[3] = {1.0, 0.5, 0.25};
    for (size_t i = 0; i < records.size(); ++i) {
        const shared::IrradiancePayload& r = records[i].payload;
        const glm::vec3 irradiance = vec3_of(r.irradiance);
        const shared::float4 translation[3] = {r.translation_r, r.translation_g, r.translation_b};
        const shared::float4 rotation[3] = {r.rotation_r, r.rotation_g, r.rotation_b};
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(irradiance[c], pi * radiance[c], 1e-5 * pi * radiance[c]) << i;
            EXPECT_LT(glm::length(vec3_of(translation[c])), 1e-6f) << i;
            EXPECT_LT(glm::length(vec3_of(rotation[c])), 1e-5f * irradiance[c]) << i;
        }
        EXPECT_TRUE(std::isinf(records[i].host.harmonic_distance)) << i;
        EXPECT_TRUE(std::isinf(records[i].host.min_distance)) << i;
    }
}

// The first record index, from `first`, one of whose pole strata (j = 0, cell k < n) the
// generator jitters onto the pole itself (zeta = 0: the top 24 bits of its word are zero, once
// in 2^24), for records of cache level 0 sampled with `seed` (irradiance_records.h: words 0 and 1
// of the stream (seed_lo ^ RC_IC_RNG_DOMAIN, seed_hi; record, cell) are the cell's jitter).
uint32_t record_with_a_pole_sample(uint64_t seed, int n, uint32_t first) {
    const auto lo = static_cast<uint32_t>(seed) ^ RC_IC_RNG_DOMAIN;
    const auto hi = static_cast<uint32_t>(seed >> 32);
    for (uint32_t record = first;; ++record) {
        for (int k = 0; k < n; ++k) {
            if (shared::rc_uint_to_unit_float(
                    shared::rc_rng_word(lo, hi, record, static_cast<uint32_t>(k), 0u)) == 0.0f) {
                return record;
            }
        }
    }
}

// A record one of whose strata is jittered exactly onto its normal (theta = 0, where the
// azimuthal walls' term of the translational gradient divides by sin(theta)) still gets finite
// gradients: under a constant sky, E = pi L and no gradient at all, as for any other record.
TEST(IcRecord, AStratumOnThePoleKeepsTheGradientsFinite) {
    CacheFixture f(scene_from_json("ic_pole", kConstantSky));
    RecordSampling sampling = strata_for(16);
    sampling.include_emission = true;
    sampling.seed = 5;
    const uint32_t index = record_with_a_pole_sample(sampling.seed, sampling.n, 0);
    const shared::IrradiancePayload r =
        f.cache.compute_records({site_at({0, 0, 0}, {0, 1, 0})}, index, sampling)[0].payload;
    const shared::float4 translation[3] = {r.translation_r, r.translation_g, r.translation_b};
    const shared::float4 rotation[3] = {r.rotation_r, r.rotation_g, r.rotation_b};
    const double radiance[3] = {1.0, 0.5, 0.25};
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR((&r.irradiance.x)[c], 3.14159265 * radiance[c], 1e-5) << c;
        EXPECT_TRUE(std::isfinite(glm::length(vec3_of(translation[c])))) << c;
        EXPECT_LT(glm::length(vec3_of(translation[c])), 1e-6f) << c;
        EXPECT_LT(glm::length(vec3_of(rotation[c])), 1e-5f) << c;
    }
}

// Projected solid angle of triangle (a, b, c) seen from p with normal n, the triangle entirely
// above p's tangent plane (Lambert): |1/2 sum over edges of theta_i n . unit(v_i x v_i+1)|.
double projected_solid_angle(glm::dvec3 p, glm::dvec3 n, const glm::dvec3 v[3]) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 a = glm::normalize(v[i] - p);
        const glm::dvec3 b = glm::normalize(v[(i + 1) % 3] - p);
        const double theta = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
        sum += theta * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return 0.5 * std::fabs(sum);
}

// The emitter: a 4 x 4 rectangle of radiance (2, 1, 0.5) tilted 30 degrees over the record,
// facing it; nothing else in the scene.
const char* kTiltedEmitter = R"({
    "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40,
               "resolution": [16, 16]},
    "materials": {"black": {"type": "diffuse", "reflectance": 0}},
    "shapes": [{"type": "rectangle", "material": "black",
                "transform": [{"scale": 2}, {"rotate": {"axis": [1, 0, 0], "angle": 150}},
                              {"translate": [0.4, 0.5, 1.5]}],
                "emitter": {"type": "area", "radiance": [2.0, 1.0, 0.5]}}]
})";

struct AnalyticEmitter {
    std::vector<std::array<glm::dvec3, 3>> triangles;
    double irradiance(glm::dvec3 p, glm::dvec3 n) const {
        double e = 0.0;
        for (const auto& t : triangles) {
            e += 2.0 * projected_solid_angle(p, glm::normalize(n), t.data());  // red: L = 2
        }
        return e;
    }
};

AnalyticEmitter emitter_of(const Scene& scene) {
    AnalyticEmitter emitter;
    for (size_t i = 0; i < scene.mesh.triangles.size(); ++i) {
        if (scene.shading[i].light < 0) {
            continue;
        }
        const glm::uvec3 t = scene.mesh.triangles[i];
        emitter.triangles.push_back({glm::dvec3(scene.mesh.positions[t.x]),
                                     glm::dvec3(scene.mesh.positions[t.y]),
                                     glm::dvec3(scene.mesh.positions[t.z])});
    }
    return emitter;
}

// The record's irradiance against Lambert's formula, its translational gradient against central
// differences of that formula along three axes, and its rotational gradient against central
// differences over small rotations of the normal about three axes. Tolerances: 0.5% for E
// (stratified sampling of an emitter with straight edges), 3% of the gradient's magnitude for
// each gradient (the estimates see the emitter's edges at the strata's resolution: about 1% off
// here; a 10% error in the radial-wall term alone is about 5%).
TEST(IcRecord, GradientsMatchFiniteDifferencesUnderATiltedEmitter) {
    CacheFixture f(scene_from_json("ic_tilted", kTiltedEmitter));
    const AnalyticEmitter emitter = emitter_of(f.device.scene);
    ASSERT_EQ(emitter.triangles.size(), 2u);
    RecordSampling sampling = strata_for(40000);
    sampling.include_emission = true;
    sampling.seed = 11;
    const glm::dvec3 p(0.1, -0.2, 0.0);
    const glm::dvec3 n(0.0, 0.0, 1.0);
    const shared::IrradiancePayload r =
        f.cache.compute_records({site_at(p, n)}, 0, sampling)[0].payload;
    const double e = emitter.irradiance(p, n);
    ASSERT_GT(e, 0.5);
    EXPECT_NEAR(r.irradiance.x, e, 0.005 * e);

    const double h = 1e-4;
    glm::dvec3 translational;
    glm::dvec3 rotational;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 step(0.0);
        step[axis] = h;
        translational[axis] =
            (emitter.irradiance(p + step, n) - emitter.irradiance(p - step, n)) / (2.0 * h);
        // The normal turned by the small angle h about `axis`.
        const glm::dvec3 omega = step;
        const glm::dvec3 plus = n + glm::cross(omega, n);
        const glm::dvec3 minus = n - glm::cross(omega, n);
        rotational[axis] = (emitter.irradiance(p, plus) - emitter.irradiance(p, minus)) / (2.0 * h);
    }
    // The record's gradient is the tangent-plane part of E's gradient.
    translational -= glm::dot(translational, n) * n;
    const glm::dvec3 measured_translation(vec3_of(r.translation_r));
    EXPECT_LT(glm::length(measured_translation - translational), 0.03 * glm::length(translational))
        << "record (" << measured_translation.x << ", " << measured_translation.y << ", "
        << measured_translation.z << ") finite differences (" << translational.x << ", "
        << translational.y << ", " << translational.z << ")";
    // The rotational gradient predicts dE = (n x n') . grad_r for n' = n + omega x n, that is
    // (n x (omega x n)) . grad_r = omega . (grad_r - (grad_r . n) n) for unit n: the derivative
    // about axis k is the tangential part of grad_r along k.
    const glm::dvec3 grad_r(vec3_of(r.rotation_r));
    const glm::dvec3 predicted = grad_r - glm::dot(grad_r, n) * n;
    EXPECT_LT(glm::length(predicted - rotational), 0.03 * glm::length(rotational))
        << "record (" << predicted.x << ", " << predicted.y << ", " << predicted.z
        << ") finite differences (" << rotational.x << ", " << rotational.y << ", " << rotational.z
        << ")";
    EXPECT_GT(glm::length(rotational), 0.05 * e);
    EXPECT_GT(glm::length(translational), 0.05 * e);
}

// The same sites, seed and sampling give bitwise the same records; another seed does not.
TEST(IcRecord, RecordsAreDeterministic) {
    CacheFixture f(scene_from_json("ic_tilted_determinism", kTiltedEmitter));
    RecordSampling sampling = strata_for(256);
    sampling.include_emission = true;
    const std::vector<RecordSite> sites = {site_at({0, 0, 0}, {0, 0, 1}),
                                           site_at({0.5, 0, 0}, {0.1, 0, 1})};
    const std::vector<ComputedRecord> a = f.cache.compute_records(sites, 7, sampling);
    const std::vector<ComputedRecord> b = f.cache.compute_records(sites, 7, sampling);
    for (size_t i = 0; i < sites.size(); ++i) {
        EXPECT_EQ(0, std::memcmp(&a[i].payload, &b[i].payload, sizeof a[i].payload)) << i;
    }
    sampling.seed = 1;
    EXPECT_NE(vec3_of(f.cache.compute_records(sites, 7, sampling)[0].payload.irradiance),
              vec3_of(a[0].payload.irradiance));
}

}  // namespace
}  // namespace rc
