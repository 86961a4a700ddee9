// Irradiance caching's records in the shared store (host/methods/irradiance_cache/
// irradiance_records.cpp: the gradient limit on R, the gradients scaled when the clamp raised R)
// and the device's weighted interpolation (rc_ic_gather) against brute force on the host.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <random>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "methods/irradiance_cache/irradiance_cache.h"
#include "methods/irradiance_cache/irradiance_records.h"
#include "scene/device_scene.h"
#include "test_support.h"

namespace rc {
namespace {

glm::vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    return glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
}

shared::float4 float4_of(glm::vec3 v) { return {v.x, v.y, v.z, 0.0f}; }
glm::dvec3 dvec3_of(const shared::float4& v) { return {v.x, v.y, v.z}; }

// A record with random irradiance and gradients at a random place in a 10-unit box; its
// harmonic mean distance spans four decades.
ComputedRecord random_record(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    ComputedRecord r;
    const glm::vec3 n = random_unit(rng);
    r.record = make_record(10.0f * glm::vec3(unit(rng), unit(rng), unit(rng)), n);
    r.payload.irradiance =
        float4_of(glm::vec3(0.5f + unit(rng), 0.5f + unit(rng), 0.5f + unit(rng)));
    shared::float4* rotation[3] = {&r.payload.rotation_r, &r.payload.rotation_g,
                                   &r.payload.rotation_b};
    shared::float4* translation[3] = {&r.payload.translation_r, &r.payload.translation_g,
                                      &r.payload.translation_b};
    for (int c = 0; c < 3; ++c) {
        *rotation[c] = float4_of(0.3f * (unit(rng) - 0.5f) * random_unit(rng));
        glm::vec3 t = 0.5f * unit(rng) * random_unit(rng);
        *translation[c] = float4_of(t - glm::dot(t, n) * n);
    }
    r.host.harmonic_distance = std::pow(10.0f, -2.0f + 4.0f * unit(rng));
    r.host.min_distance = 0.5f * r.host.harmonic_distance;
    r.host.r_min = 0.0f;
    r.host.r_max = 1e30f;
    return r;
}

// R is limited by the translational gradient: |grad E| R <= E (luminance).
TEST(IcRecords, GradientLimitsTheRadius) {
    RecordStore store = irradiance_store(0.5f);
    ComputedRecord r;
    r.payload.irradiance = float4_of(glm::vec3(2.0f));
    r.payload.translation_r = r.payload.translation_g = r.payload.translation_b =
        float4_of(glm::vec3(8.0f, 0.0f, 0.0f));
    r.host.harmonic_distance = 10.0f;
    r.host.r_max = 100.0f;
    EXPECT_FLOAT_EQ(irradiance_radius_limit(r.payload), 0.25f);
    insert_irradiance_record(store, r);
    EXPECT_FLOAT_EQ(store.host_data()[0].radius, 0.25f);
    EXPECT_FLOAT_EQ(store.records()[0].radius, 0.25f);
    // No gradient: no limit.
    r.payload.translation_r = r.payload.translation_g = r.payload.translation_b = {};
    EXPECT_TRUE(std::isinf(irradiance_radius_limit(r.payload)));
}

// The kernels' form clamps R to [R_min, R_max] and, when that raised R, scales the gradients by
// R / R' so extrapolation to the larger border changes E no more than it would have at R; the
// store keeps the payload as computed.
TEST(IcRecords, DevicePayloadClampsTheRadiusAndScalesTheGradients) {
    RecordStore store = irradiance_store(0.5f);
    ComputedRecord r;
    r.payload.irradiance = float4_of(glm::vec3(1.0f));
    r.payload.rotation_g = float4_of(glm::vec3(0.0f, 0.4f, 0.0f));
    r.payload.translation_b = float4_of(glm::vec3(0.2f, 0.0f, 0.0f));
    r.host.harmonic_distance = 1.0f;
    r.host.r_min = 4.0f;
    r.host.r_max = 8.0f;
    insert_irradiance_record(store, r);
    r.record = make_record(glm::vec3(100.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    r.host.harmonic_distance = 50.0f;
    insert_irradiance_record(store, r);
    EXPECT_FLOAT_EQ(store.records()[0].radius, 4.0f);
    const shared::IrradiancePayload raised = device_payload(store, 0);
    EXPECT_FLOAT_EQ(raised.rotation_g.y, 0.1f);
    EXPECT_FLOAT_EQ(raised.translation_b.x, 0.05f);
    EXPECT_FLOAT_EQ(raised.irradiance.x, 1.0f);
    EXPECT_FLOAT_EQ(store.payload<shared::IrradiancePayload>(0).rotation_g.y, 0.4f);
    EXPECT_FLOAT_EQ(store.records()[1].radius, 8.0f);
    EXPECT_FLOAT_EQ(device_payload(store, 1).rotation_g.y, 0.4f);  // lowering R keeps them
}

// The weighted sum of one record at (p, n), in double precision from the definitions: Ward's
// weight less 1/a, capped; zero behind the point, past the nearest occluder and beyond the
// influence border; extrapolation by both gradients, clamped at zero.
void add_record(const shared::Record& record, const shared::IrradiancePayload& r, glm::dvec3 p,
                glm::dvec3 n, double a, glm::dvec4& sum) {
    const glm::dvec3 pi = dvec3_of(record.position);
    const glm::dvec3 ni = glm::normalize(dvec3_of(record.normal));
    const glm::dvec3 o = dvec3_of(r.occluder);
    const double radius = record.radius;
    const glm::dvec3 offset = p - pi;
    if (glm::dot(offset, 0.5 * (n + ni)) < -1e-3 * a * radius ||
        glm::dot(offset, o) > glm::dot(o, o)) {
        return;
    }
    const double error =
        glm::length(offset) / radius + std::sqrt(std::max(0.0, 1.0 - glm::dot(n, ni)));
    if (error >= a) {
        return;
    }
    const double w = std::min(1.0 / std::max(error, 1e-12) - 1.0 / a,
                              static_cast<double>(kIrradianceCacheMaxWeight));
    const glm::dvec3 axis = glm::cross(ni, n);
    const shared::float4 rotation[3] = {r.rotation_r, r.rotation_g, r.rotation_b};
    const shared::float4 translation[3] = {r.translation_r, r.translation_g, r.translation_b};
    const double e[3] = {r.irradiance.x, r.irradiance.y, r.irradiance.z};
    for (int c = 0; c < 3; ++c) {
        const double extrapolated =
            e[c] + glm::dot(axis, glm::dvec3(rotation[c].x, rotation[c].y, rotation[c].z)) +
            glm::dot(offset, glm::dvec3(translation[c].x, translation[c].y, translation[c].z));
        sum[c] += w * std::max(0.0, extrapolated);
    }
    sum.w += w;
}

// The device's sums over random records at random query points equal the host's brute force
// over every record within 1e-5 relative.
TEST(IcRecords, GatherEqualsBruteForceWeightedAverage) {
    const Scene scene = test::load_cornell_box();
    const Bvh bvh = build_bvh(scene.mesh);
    Context& context = test::shared_context();
    const DeviceBvh device_bvh(context, bvh);
    const DeviceScene device_scene(context, scene);
    IrradianceCache cache(context, scene, device_bvh, device_scene);

    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<shared::Record> records;
    std::vector<RecordHostData> host;
    std::vector<std::byte> payloads(500 * sizeof(shared::IrradiancePayload));
    for (int i = 0; i < 500; ++i) {
        ComputedRecord r = random_record(rng);
        r.host.radius = 0.5f + 3.0f * unit(rng);
        // Every other record sees a near occluder beside it.
        if (i % 2 == 0) {
            const glm::vec3 side =
                glm::normalize(glm::cross(record_normal(r.record), random_unit(rng)));
            r.payload.occluder = float4_of((0.2f + unit(rng)) * side);
        }
        records.push_back(r.record);
        host.push_back(r.host);
        std::memcpy(payloads.data() + i * sizeof r.payload, &r.payload, sizeof r.payload);
    }
    RecordStore store = irradiance_store(0.4f);
    store.restore(records, host, payloads);
    const std::vector<shared::IrradiancePayload> device = device_payloads(store);

    // Queries near records: within their influence, off the tangent plane a little, normals
    // turned a little.
    std::vector<shared::GBufferSample> queries;
    for (int q = 0; q < 4000; ++q) {
        const size_t k = rng() % records.size();
        const glm::vec3 p = record_position(records[k]) +
                            0.5f * host[k].radius * unit(rng) * random_unit(rng) +
                            0.01f * random_unit(rng);
        const glm::vec3 n =
            glm::normalize(record_normal(records[k]) + 0.3f * unit(rng) * random_unit(rng));
        shared::GBufferSample g{};
        g.position = {p.x, p.y, p.z, 0.0f};
        g.normal = {n.x, n.y, n.z, 1.0f};
        g.info = {0, q, 0, 1};
        queries.push_back(g);
    }
    const std::vector<shared::float4> gathered = cache.gather(store, queries);
    ASSERT_EQ(gathered.size(), queries.size());
    size_t covered = 0;
    for (size_t q = 0; q < queries.size(); ++q) {
        const glm::dvec3 p(queries[q].position.x, queries[q].position.y, queries[q].position.z);
        const glm::dvec3 n = glm::normalize(
            glm::dvec3(queries[q].normal.x, queries[q].normal.y, queries[q].normal.z));
        glm::dvec4 expected(0.0);
        for (size_t i = 0; i < device.size(); ++i) {
            add_record(store.records()[i], device[i], p, n, store.accuracy(), expected);
        }
        const double got[4] = {gathered[q].x, gathered[q].y, gathered[q].z, gathered[q].w};
        for (int c = 0; c < 4; ++c) {
            EXPECT_NEAR(got[c], expected[c], 1e-5 * std::max(1.0, std::fabs(expected[c])))
                << "query " << q << ", component " << c;
        }
        covered += expected.w > 0.0 ? 1 : 0;
    }
    EXPECT_GT(covered, queries.size() / 4);
}

}  // namespace
}  // namespace rc
