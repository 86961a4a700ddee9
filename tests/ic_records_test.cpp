// The irradiance cache's record store (host/methods/irradiance_records.cpp): neighbor clamping, the
// radius limits and the record grid. The device's weighted interpolation is in ic_gather_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "methods/irradiance_cache/irradiance_records.h"
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

}  // namespace
}  // namespace rc
