// Irradiance caching's records in the shared store (host/methods/irradiance_cache/
// irradiance_records.cpp: the gradient limit on R, the gradients scaled when the clamp raised R).
// The device's weighted interpolation is tested in ic_gather_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <random>

#include "methods/caching/irradiance_records.h"
#include "test_support.h"

namespace rc {
namespace {

shared::float4 float4_of(glm::vec3 v) { return {v.x, v.y, v.z, 0.0f}; }

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

}  // namespace
}  // namespace rc
