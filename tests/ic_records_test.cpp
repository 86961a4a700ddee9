// The irradiance cache's record store (host/methods/irradiance_records.cpp) and the device's
// weighted interpolation (rc_ic_gather) against brute force on the host.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// A record with random irradiance and gradients at a random place in a 10-unit box; its
// harmonic mean distance spans four decades, so neighbor clamping has work to do.
CacheRecord random_record(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    CacheRecord r;
    r.position = 10.0f * glm::vec3(unit(rng), unit(rng), unit(rng));
    r.normal = random_unit(rng);
    r.irradiance = glm::vec3(0.5f + unit(rng), 0.5f + unit(rng), 0.5f + unit(rng));
    for (int c = 0; c < 3; ++c) {
        r.rotation[c] = 0.3f * (unit(rng) - 0.5f) * random_unit(rng);
        glm::vec3 t = 0.5f * unit(rng) * random_unit(rng);
        r.translation[c] = t - glm::dot(t, r.normal) * r.normal;
    }
    r.harmonic_distance = std::pow(10.0f, -2.0f + 4.0f * unit(rng));
    r.min_distance = 0.5f * r.harmonic_distance;
    r.r_min = 0.0f;
    r.r_max = 1e30f;
    return r;
}

// After every insertion every pair of overlapping records satisfies R_j <= R_k + |p_j - p_k| on
// the unclamped radii (neighbor clamping), and no insertion raises a radius.
TEST(IcRecords, NeighborClampingKeepsTheTriangleInequalityAfterEveryInsertion) {
    std::mt19937 rng(17);
    RecordStore store(0.3f);
    std::vector<float> before;
    size_t clamped = 0;
    for (int i = 0; i < 300; ++i) {
        CacheRecord record = random_record(rng);
        if (i % 3 == 0) {
            record.r_max = 0.5f;  // some records capped from above
        }
        const size_t j = store.insert(record);
        const std::vector<CacheRecord>& records = store.records();
        ASSERT_EQ(j, records.size() - 1);
        EXPECT_LE(records[j].radius, record.harmonic_distance);
        EXPECT_LE(records[j].radius, record.r_max);
        clamped += records[j].radius < std::min(record.harmonic_distance, record.r_max) ? 1 : 0;
        for (size_t k = 0; k < before.size(); ++k) {
            ASSERT_LE(records[k].radius, before[k]) << "insertion " << i << " raised record " << k;
        }
        for (size_t a = 0; a < records.size(); ++a) {
            for (size_t b = 0; b < records.size(); ++b) {
                const float d = glm::length(records[a].position - records[b].position);
                if (a != b && d < records[a].radius + records[b].radius) {
                    ASSERT_LE(records[a].radius, records[b].radius + d * (1.0f + 1e-6f))
                        << "after insertion " << i << ": records " << a << " and " << b;
                }
            }
        }
        before.clear();
        for (const CacheRecord& r : records) {
            before.push_back(r.radius);
        }
    }
    EXPECT_GT(clamped, 30u);  // the test exercised clamping
}

// R is limited by the translational gradient: |grad E| R <= E (luminance).
TEST(IcRecords, GradientLimitsTheRadius) {
    RecordStore store(0.5f);
    CacheRecord r;
    r.irradiance = glm::vec3(2.0f);
    for (int c = 0; c < 3; ++c) {
        r.translation[c] = glm::vec3(8.0f, 0.0f, 0.0f);
    }
    r.harmonic_distance = 10.0f;
    r.r_max = 100.0f;
    store.insert(r);
    EXPECT_FLOAT_EQ(store.records()[0].radius, 0.25f);
}

// The device form clamps R to [R_min, R_max] and, when that raised R, scales the gradients by
// R / R' so extrapolation to the larger border changes E no more than it would have at R.
TEST(IcRecords, DeviceRecordClampsTheRadiusAndScalesTheGradients) {
    RecordStore store(0.5f);
    CacheRecord r;
    r.irradiance = glm::vec3(1.0f);
    r.rotation[1] = glm::vec3(0.0f, 0.4f, 0.0f);
    r.translation[2] = glm::vec3(0.2f, 0.0f, 0.0f);
    r.harmonic_distance = 1.0f;
    r.r_min = 4.0f;
    r.r_max = 8.0f;
    store.insert(r);
    r.position = glm::vec3(100.0f, 0.0f, 0.0f);
    r.harmonic_distance = 50.0f;
    store.insert(r);
    const shared::IrradianceRecord raised = store.device_record(0);
    EXPECT_FLOAT_EQ(raised.position.w, 4.0f);
    EXPECT_FLOAT_EQ(raised.rotation_g.y, 0.1f);
    EXPECT_FLOAT_EQ(raised.translation_b.x, 0.05f);
    const shared::IrradianceRecord lowered = store.device_record(1);
    EXPECT_FLOAT_EQ(lowered.position.w, 8.0f);
    EXPECT_FLOAT_EQ(lowered.rotation_g.y, 0.4f);  // lowering R keeps the gradients
}

// Every record whose influence sphere contains a point is listed in the point's grid cell.
TEST(IcRecords, GridListsEveryRecordCoveringAPoint) {
    std::mt19937 rng(5);
    RecordStore store(0.4f);
    for (int i = 0; i < 400; ++i) {
        store.insert(random_record(rng));
    }
    const RecordGridData data = store.build_grid(4096);
    const std::vector<shared::IrradianceRecord> device = store.device_records();
    std::uniform_real_distribution<float> coordinate(-1.0f, 11.0f);
    size_t covered = 0;
    for (int q = 0; q < 5000; ++q) {
        const glm::vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        const glm::vec3 g =
            (p - glm::vec3(data.grid.origin.x, data.grid.origin.y, data.grid.origin.z)) *
            data.grid.inv_cell.x;
        const glm::ivec3 c(glm::floor(g));
        const bool inside = c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < data.grid.dims.x &&
                            c.y < data.grid.dims.y && c.z < data.grid.dims.z;
        std::vector<int> listed;
        if (inside) {
            const int cell = (c.z * data.grid.dims.y + c.y) * data.grid.dims.x + c.x;
            listed.assign(data.cell_records.begin() + data.cell_start[cell],
                          data.cell_records.begin() + data.cell_start[cell + 1]);
        }
        for (size_t i = 0; i < device.size(); ++i) {
            const glm::vec3 centre(device[i].position.x, device[i].position.y,
                                   device[i].position.z);
            if (glm::length(p - centre) < store.accuracy() * device[i].position.w) {
                ++covered;
                ASSERT_TRUE(inside) << "query " << q;
                ASSERT_NE(std::find(listed.begin(), listed.end(), static_cast<int>(i)),
                          listed.end())
                    << "query " << q << ", record " << i;
            }
        }
    }
    EXPECT_GT(covered, 200u);
}

// The weighted sum of one record at (p, n), in double precision from the definitions: Ward's
// weight less 1/a, capped; zero behind the point, past the nearest occluder and beyond the
// influence border; extrapolation by both gradients, clamped at zero.
void add_record(const shared::IrradianceRecord& r, glm::dvec3 p, glm::dvec3 n, double a,
                glm::dvec4& sum) {
    const glm::dvec3 pi(r.position.x, r.position.y, r.position.z);
    const glm::dvec3 ni = glm::normalize(glm::dvec3(r.normal.x, r.normal.y, r.normal.z));
    const glm::dvec3 o(r.occluder.x, r.occluder.y, r.occluder.z);
    const double radius = r.position.w;
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
    std::vector<CacheRecord> records;
    for (int i = 0; i < 500; ++i) {
        CacheRecord r = random_record(rng);
        r.radius = 0.5f + 3.0f * unit(rng);
        // Every other record sees a near occluder beside it.
        if (i % 2 == 0) {
            const glm::vec3 side = glm::normalize(glm::cross(r.normal, random_unit(rng)));
            r.occluder = (0.2f + unit(rng)) * side;
        }
        records.push_back(r);
    }
    RecordStore store(0.4f);
    store.restore(records);
    const std::vector<shared::IrradianceRecord> device = store.device_records();

    // Queries near records: within their influence, off the tangent plane a little, normals
    // turned a little.
    std::vector<shared::GBufferSample> queries;
    for (int q = 0; q < 4000; ++q) {
        const CacheRecord& r = records[rng() % records.size()];
        const glm::vec3 p =
            r.position + 0.5f * r.radius * unit(rng) * random_unit(rng) + 0.01f * random_unit(rng);
        const glm::vec3 n = glm::normalize(r.normal + 0.3f * unit(rng) * random_unit(rng));
        shared::GBufferSample g{};
        g.position = {p.x, p.y, p.z, 0.0f};
        g.normal = {n.x, n.y, n.z, 0.0f};
        g.diffuse = 1.0f;
        g.primitive = 0;
        g.served = 1;
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
        for (const shared::IrradianceRecord& r : device) {
            add_record(r, p, n, store.accuracy(), expected);
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
