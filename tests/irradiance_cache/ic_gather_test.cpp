// Irradiance-cache interpolation on the device (the gather the camera samples use) against the
// course's formulas evaluated by brute force on the host: every record, no grid, double precision.
// The reference is written from the papers, not from the kernel's code:
//   Ward et al. 1988 eq. 5 (course "Generalized Error Estimate"): the error estimate
//     eps_i(p) = |p - p_i| / R_i + sqrt(1 - n . n_i), the set S = {i : 1 / eps_i > 1/a};
//   course "Weighting Function Revisited", third form: w_i = 1 / eps_i - 1/a (zero at the border),
//     capped near the record (kRecordMaxWeight, where eps_i -> 0);
//   Ward et al. 1988 eq. 6 (course "Additional Constraint"): records in front of p are left out,
//     d_i(p) = (p - p_i) . (n + n_i) / 2 < 0;
//   DESIGN.md §6.2 step 4-5 and the cache's own rule: a record whose nearest hit lies to the side
//   at
//     tangent offset o does not reach past that occluder, i.e. past the plane through p_i + o
//     perpendicular to o;
//   Ward and Heckbert 1992 (course "Irradiance Gradients", eq. 5): the record's irradiance at (p,
//   n)
//     is E_i + (n_i x n) . grad_r E_i + (p - p_i) . grad_t E_i, clamped at zero (DESIGN.md §6.2
//     step 5);
// and the device must return (sum w E', sum w).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <random>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "image_options.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/caching/irradiance_records.h"
#include "scene/device_scene.h"
#include "test_support.h"

namespace rc {
namespace {

// A record as the papers describe it, after the radius is final (no clamping left to do).
struct PaperRecord {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 irradiance{0.0f};
    glm::vec3 rotation[3] = {};     // grad_r E per RGB channel
    glm::vec3 translation[3] = {};  // grad_t E per RGB channel
    float radius = 1.0f;            // R_i
    glm::vec3 occluder{0.0f};       // tangent offset of the nearest side hit; zero: none
};

struct Query {
    glm::vec3 position;
    glm::vec3 normal;
};

// The one place that knows the host record store and the gather entry point: the records go in
// with their radius final (R_min 0, R_max unbounded, no neighbor clamping on restore).
std::vector<glm::dvec4> device_gather(const std::vector<PaperRecord>& records,
                                      const std::vector<Query>& queries, float accuracy) {
    static const Scene scene = test::load_cornell_box();
    Context& context = test::shared_context();
    static const Bvh bvh = build_bvh(scene.mesh, context.bvh_layout());
    static const DeviceBvh device_bvh(context, bvh);
    static const DeviceScene device_scene(context, scene);
    CachePipeline cache({context, scene, device_bvh, device_scene});
    std::vector<shared::Record> stored;
    std::vector<RecordHostData> host;
    std::vector<std::byte> payloads(records.size() * sizeof(shared::IrradiancePayload));
    const auto float4_of = [](glm::vec3 v) { return shared::float4{v.x, v.y, v.z, 0.0f}; };
    for (size_t k = 0; k < records.size(); ++k) {
        const PaperRecord& r = records[k];
        stored.push_back(make_record(r.position, r.normal));
        RecordHostData h;
        h.harmonic_distance = r.radius;
        h.min_distance = r.radius;
        h.r_min = 0.0f;
        h.r_max = std::numeric_limits<float>::max();
        h.radius = r.radius;
        host.push_back(h);
        shared::IrradiancePayload payload{};
        payload.irradiance = float4_of(r.irradiance);
        payload.rotation_r = float4_of(r.rotation[0]);
        payload.rotation_g = float4_of(r.rotation[1]);
        payload.rotation_b = float4_of(r.rotation[2]);
        payload.translation_r = float4_of(r.translation[0]);
        payload.translation_g = float4_of(r.translation[1]);
        payload.translation_b = float4_of(r.translation[2]);
        payload.occluder = float4_of(r.occluder);
        std::memcpy(payloads.data() + k * sizeof payload, &payload, sizeof payload);
    }
    RecordStore store = irradiance_store(accuracy);
    store.restore(stored, host, payloads);
    std::vector<shared::GBufferSample> samples;
    for (size_t q = 0; q < queries.size(); ++q) {
        shared::GBufferSample g{};
        g.position = {queries[q].position.x, queries[q].position.y, queries[q].position.z, 0.0f};
        g.normal = {queries[q].normal.x, queries[q].normal.y, queries[q].normal.z, 0.0f};
        g.diffuse = 1.0f;
        g.primitive = 0;
        g.served = 1;
        samples.push_back(g);
    }
    std::vector<glm::dvec4> sums;
    for (const shared::float4& s : cache.gather(store, samples)) {
        sums.emplace_back(s.x, s.y, s.z, s.w);
    }
    return sums;
}

constexpr double kMaxWeight = kRecordMaxWeight;

glm::dvec3 d3(glm::vec3 v) { return glm::dvec3(v); }

// One record's contribution at (p, n) by the formulas above, and the magnitude of the float terms
// it is made of (for the rounding bound). `ambiguous` is set when p lies within `band` of the
// behind test's or the occluder's plane, where the kernel's tolerances may decide either way.
// Points within `coplanar` of the behind test's plane are taken to lie on it (d_i = 0: accepted):
// points of one flat surface, whose float positions scatter off its plane by rounding alone.
struct Contribution {
    glm::dvec4 sum{0.0};        // w E' (rgb), w
    glm::dvec4 magnitude{0.0};  // the same with every term taken by absolute value
    bool ambiguous = false;
    bool rejected = false;  // in S, but behind p or past the occluder
    bool clamped = false;   // some channel's extrapolation clamped at zero
};

Contribution contribution(const PaperRecord& r, glm::dvec3 p, glm::dvec3 n, double a,
                          double coplanar = 0.0) {
    Contribution out;
    const glm::dvec3 pi = d3(r.position);
    const glm::dvec3 ni = glm::normalize(d3(r.normal));
    const double epsilon =
        glm::length(p - pi) / r.radius + std::sqrt(std::max(0.0, 1.0 - glm::dot(n, ni)));
    if (!(1.0 / epsilon > 1.0 / a)) {
        return out;  // not in S
    }
    const double band = 1e-2 * a * r.radius;
    double behind = glm::dot(p - pi, 0.5 * (n + ni));  // eq. 6
    if (std::fabs(behind) <= coplanar) {
        behind = 0.0;
    }
    // (At p = p_i exactly the offset is zero in any arithmetic: d_i = 0, accepted, unambiguous.)
    out.ambiguous = std::fabs(behind) < band && p != pi && behind != 0.0;
    if (behind < 0.0) {
        out.rejected = true;
        return out;
    }
    const double reach = glm::length(d3(r.occluder));
    if (reach > 0.0) {
        const double past = glm::dot(p - pi, d3(r.occluder) / reach) - reach;
        out.ambiguous = out.ambiguous || std::fabs(past) < band;
        if (past > 0.0) {
            out.rejected = true;
            return out;
        }
    }
    const double w = std::min(1.0 / epsilon - 1.0 / a, kMaxWeight);
    for (int c = 0; c < 3; ++c) {
        const double rotational = glm::dot(glm::cross(ni, n), d3(r.rotation[c]));
        const double translational = glm::dot(p - pi, d3(r.translation[c]));
        const double extrapolated = r.irradiance[c] + rotational + translational;
        out.clamped = out.clamped || extrapolated < 0.0;
        out.sum[c] = w * std::max(0.0, extrapolated);
        out.magnitude[c] = (1.0 / epsilon) * (std::fabs(r.irradiance[c]) + std::fabs(rotational) +
                                              std::fabs(translational));
    }
    out.sum.w = w;
    out.magnitude.w = std::min(1.0 / epsilon, kMaxWeight);
    return out;
}

glm::vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    return glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
}

// Random records in a 4-unit box, normals about three directions (surfaces), so that influence
// regions overlap: radii 0.5 to 3.5 (influence 0.2 to 1.4 at a = 0.4), positive
// irradiance, gradients large enough that extrapolation sometimes clamps at zero, and every other
// record with an occluder beside it.
std::vector<PaperRecord> random_records(std::mt19937& rng, int count) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<PaperRecord> records;
    for (int i = 0; i < count; ++i) {
        PaperRecord r;
        r.position = 4.0f * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 surfaces[3] = {{0, 1, 0}, {1, 0, 0}, {0.6f, 0, 0.8f}};
        r.normal = glm::normalize(surfaces[i % 3] + 0.15f * random_unit(rng));
        r.irradiance = glm::vec3(0.5f + unit(rng), 0.5f + unit(rng), 0.5f + unit(rng));
        for (int c = 0; c < 3; ++c) {
            r.rotation[c] = 2.0f * (unit(rng) - 0.5f) * random_unit(rng);
            const glm::vec3 t = 3.0f * unit(rng) * random_unit(rng);
            r.translation[c] = t - glm::dot(t, r.normal) * r.normal;
        }
        r.radius = 0.5f + 3.0f * unit(rng);
        if (i % 2 == 0) {
            const glm::vec3 side = glm::normalize(glm::cross(r.normal, random_unit(rng)));
            r.occluder = (0.05f + 0.5f * unit(rng)) * side;
        }
        records.push_back(r);
    }
    return records;
}

TEST(IcGather, EqualsTheCoursesWeightedSumOverEveryRecord) {
    const float a = 0.4f;
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const std::vector<PaperRecord> records = random_records(rng, 500);
    // Queries near random records: within their influence, a little off the tangent plane (on
    // either side, so the behind test has work), normals turned a little; and some at a record's
    // own position and normal, where the weight is capped.
    std::vector<Query> queries;
    for (int q = 0; q < 4000; ++q) {
        const PaperRecord& r = records[rng() % records.size()];
        if (q % 50 == 0) {
            queries.push_back({r.position, r.normal});
            continue;
        }
        const glm::vec3 p = r.position + 0.5f * a * r.radius * unit(rng) * random_unit(rng) +
                            0.05f * random_unit(rng);
        const glm::vec3 n = glm::normalize(r.normal + 0.3f * unit(rng) * random_unit(rng));
        queries.push_back({p, n});
    }
    const std::vector<glm::dvec4> device = device_gather(records, queries, a);
    ASSERT_EQ(device.size(), queries.size());

    size_t covered = 0, several = 0, rejected = 0, clamped = 0, capped = 0, compared = 0;
    double worst = 0.0;  // largest error relative to the magnitude
    for (size_t q = 0; q < queries.size(); ++q) {
        const glm::dvec3 p = d3(queries[q].position);
        const glm::dvec3 n = glm::normalize(d3(queries[q].normal));
        glm::dvec4 expected(0.0), magnitude(0.0);
        bool ambiguous = false;
        int contributors = 0;
        bool any_rejected = false;
        bool any_clamped = false;
        for (const PaperRecord& r : records) {
            const Contribution c = contribution(r, p, n, a);
            expected += c.sum;
            magnitude += c.magnitude;
            ambiguous = ambiguous || c.ambiguous;
            contributors += c.sum.w > 0.0 ? 1 : 0;
            any_rejected = any_rejected || c.rejected;
            any_clamped = any_clamped || (c.clamped && c.sum.w > 0.0);
        }
        if (ambiguous) {
            continue;  // within 1% of a radius of a rejection plane: either answer is right
        }
        ++compared;
        covered += contributors > 0 ? 1 : 0;
        several += contributors > 1 ? 1 : 0;
        rejected += any_rejected ? 1 : 0;
        clamped += any_clamped ? 1 : 0;
        capped += expected.w >= kMaxWeight ? 1 : 0;
        // Float rounding: each term is a handful of float operations (relative error 6e-8 each)
        // on quantities of size `magnitude`, summed over at most a few dozen records: a few 1e-7
        // of the magnitude (measured: under 2e-7), so 1e-4 is float rounding with room, and far
        // below any error in the formulas. Weights near the border (eps -> a) cancel in
        // 1/eps - 1/a, which is why the bound is relative to 1/eps, not to w; a record the kernel
        // and the reference place on opposite sides of the border weighs ~1e-6.
        for (int c = 0; c < 4; ++c) {
            const double scale = std::max(magnitude[c], 1.0);
            worst = std::max(worst, std::fabs(device[q][c] - expected[c]) / scale);
            EXPECT_NEAR(device[q][c], expected[c], 1e-4 * scale)
                << "query " << q << ", component " << c << ", " << contributors << " records";
        }
    }
    std::printf(
        "compared %zu, covered %zu, several %zu, rejected %zu, clamped %zu, capped %zu; "
        "largest error %.2g of the magnitude\n",
        compared, covered, several, rejected, clamped, capped, worst);
    // The comparison saw most queries, overlapping records, rejections and the cap.
    EXPECT_GT(compared, queries.size() * 3 / 4);
    EXPECT_GT(covered, compared / 2);
    EXPECT_GT(several, compared / 10);
    EXPECT_GT(rejected, compared / 20);
    EXPECT_GT(clamped, compared / 100);
    EXPECT_GT(capped, 20u);
}

// Radiance cache splatting (course, "Radiance Cache Splatting", Algorithms 1 and 2) on a real
// render: at every camera sample of the Cornell box, the splat buffer holds the course's weighted
// sum over every record of the render's cache (the reference above, every record, no tiles), it
// equals the world-space gather to the bit (the same records summed in the same order), and
// placement left no sample the cache serves without weight (Algorithm 2, step 4).
TEST(IcSplat, SplatBufferEqualsTheCoursesWeightedSumAndTheGather) {
    test::DeviceFrame cornell(test::load_cornell_box());
    CachePipeline cache(cornell.frame());
    auto options = test::image_options<PipelineSettings>(48, 40, 2);
    options.rays = 64;
    options.accuracy = 0.4f;
    options.bounces = 1;
    options.records_overlay = false;
    cache.render(options);
    const RecordStore& store = cache.store(0);
    const std::vector<shared::GBufferSample> samples = cache.camera_samples();
    const std::vector<shared::float4> splat =
        cache.splat(store, cache.camera(), options.spp, samples);
    const std::vector<shared::float4> gathered = cache.gather(store, samples);
    ASSERT_EQ(splat.size(), samples.size());

    std::vector<PaperRecord> records;
    for (size_t i = 0; i < store.size(); ++i) {
        const shared::Record& record = store.records()[i];
        const shared::IrradiancePayload payload = device_payload(store, i);
        const auto v = [](const shared::float4& f) { return glm::vec3(f.x, f.y, f.z); };
        PaperRecord r;
        r.position = v(record.position);
        r.normal = v(record.normal);
        r.irradiance = v(payload.irradiance);
        r.rotation[0] = v(payload.rotation_r);
        r.rotation[1] = v(payload.rotation_g);
        r.rotation[2] = v(payload.rotation_b);
        r.translation[0] = v(payload.translation_r);
        r.translation[1] = v(payload.translation_g);
        r.translation[2] = v(payload.translation_b);
        r.radius = record.radius;
        r.occluder = v(payload.occluder);
        records.push_back(r);
    }
    ASSERT_GT(records.size(), 20u);
    size_t served = 0, compared = 0;
    for (size_t q = 0; q < samples.size(); ++q) {
        ASSERT_EQ(std::memcmp(&splat[q], &gathered[q], sizeof splat[q]), 0) << "sample " << q;
        if (samples[q].served == 0) {
            EXPECT_EQ(splat[q].w, 0.0f);
            continue;
        }
        ++served;
        EXPECT_GT(splat[q].w, 0.0f) << "sample " << q << " is served but uncovered";
        const glm::dvec3 p(samples[q].position.x, samples[q].position.y, samples[q].position.z);
        const glm::dvec3 n = glm::normalize(
            glm::dvec3(samples[q].normal.x, samples[q].normal.y, samples[q].normal.z));
        glm::dvec4 expected(0.0), magnitude(0.0);
        bool ambiguous = false;
        for (const PaperRecord& r : records) {
            // The box's walls are flat: a record on the sample's wall lies on its plane up to
            // float rounding of positions (~1e-7 of the box), far below 1e-5 a R.
            const Contribution c =
                contribution(r, p, n, options.accuracy, 1e-5 * options.accuracy * r.radius);
            expected += c.sum;
            magnitude += c.magnitude;
            ambiguous = ambiguous || c.ambiguous;
        }
        if (ambiguous) {
            continue;
        }
        ++compared;
        const double got[4] = {splat[q].x, splat[q].y, splat[q].z, splat[q].w};
        for (int c = 0; c < 4; ++c) {
            // Float rounding, as in the test above.
            EXPECT_NEAR(got[c], expected[c], 1e-4 * std::max(magnitude[c], 1.0))
                << "sample " << q << ", component " << c;
        }
    }
    std::printf("%zu records, %zu samples served, %zu compared with the reference\n",
                records.size(), served, compared);
    EXPECT_GT(served, samples.size() / 2);
    EXPECT_GT(compared, served * 3 / 4);
}

}  // namespace
}  // namespace rc
