#include "methods/caching/irradiance_records.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "scene/scene_fingerprint.h"
#include "util/glm_helpers.h"

namespace rc {
namespace {

shared::float4 scaled(const shared::float4& v, float s) {
    return {s * v.x, s * v.y, s * v.z, 0.0f};
}

}  // namespace

RecordStore irradiance_store(float accuracy) {
    return RecordStore(accuracy, sizeof(shared::IrradiancePayload));
}

float irradiance_radius_limit(const shared::IrradiancePayload& payload) {
    const glm::vec3 gradient = 0.2126f * vec3_of(payload.translation_r) +
                               0.7152f * vec3_of(payload.translation_g) +
                               0.0722f * vec3_of(payload.translation_b);
    const float e = luminance(vec3_of(payload.irradiance));
    const float g = glm::length(gradient);
    if (g > 0.0f && e > 0.0f) {
        return e / g;
    }
    return std::numeric_limits<float>::infinity();
}

size_t insert_irradiance_record(RecordStore& store, const ComputedRecord& computed) {
    return store.insert(computed.record, computed.host, computed.payload,
                        irradiance_radius_limit(computed.payload));
}

void insert_irradiance_records(RecordStore& store, const std::vector<ComputedRecord>& computed) {
    std::vector<NewRecord> batch;
    batch.reserve(computed.size());
    for (const ComputedRecord& record : computed) {
        batch.push_back(
            {record.record, record.host, &record.payload, irradiance_radius_limit(record.payload)});
    }
    store.insert_batch(batch);
}

shared::IrradiancePayload device_payload(const RecordStore& store, size_t i) {
    shared::IrradiancePayload p = store.payload<shared::IrradiancePayload>(i);
    const float s = store.gradient_scale(i);
    p.rotation_r = scaled(p.rotation_r, s);
    p.rotation_g = scaled(p.rotation_g, s);
    p.rotation_b = scaled(p.rotation_b, s);
    p.translation_r = scaled(p.translation_r, s);
    p.translation_g = scaled(p.translation_g, s);
    p.translation_b = scaled(p.translation_b, s);
    return p;
}

std::vector<shared::IrradiancePayload> device_payloads(const RecordStore& store) {
    std::vector<shared::IrradiancePayload> payloads;
    payloads.reserve(store.size());
    for (size_t i = 0; i < store.size(); ++i) {
        payloads.push_back(device_payload(store, i));
    }
    return payloads;
}

CacheFileKey irradiance_cache_key(const Scene& scene, float accuracy) {
    CacheFileKey key;
    key.method = kIrradianceMethodTag;
    key.payload_bytes = sizeof(shared::IrradiancePayload);
    key.scene = scene_fingerprint(scene);
    key.scene_name = scene.path.string();
    key.accuracy = accuracy;
    return key;
}

}  // namespace rc
