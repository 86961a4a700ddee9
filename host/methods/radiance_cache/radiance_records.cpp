#include "methods/radiance_cache/radiance_records.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "scene/scene_fingerprint.h"

namespace rc {

size_t radiance_payload_floats(int order) { return 9 * static_cast<size_t>(order) * order; }

RecordStore radiance_store(float accuracy, int order) {
    return RecordStore(accuracy, radiance_payload_floats(order) * sizeof(float));
}

float radiance_radius_limit(const std::vector<float>& payload, int order) {
    const size_t count = static_cast<size_t>(order) * order;
    const float weights[3] = {0.2126f, 0.7152f, 0.0722f};
    float mean = 0.0f;
    float gx = 0.0f;
    float gy = 0.0f;
    for (size_t c = 0; c < 3; ++c) {
        mean += weights[c] * payload[c * count];
        gx += weights[c] * payload[(3 + 2 * c) * count];
        gy += weights[c] * payload[(4 + 2 * c) * count];
    }
    const float g = std::sqrt(gx * gx + gy * gy);
    if (g > 0.0f && mean > 0.0f) {
        return mean / g;
    }
    return std::numeric_limits<float>::infinity();
}

std::vector<float> device_radiance_payloads(const RecordStore& store, int order) {
    const size_t floats = radiance_payload_floats(order);
    const size_t coefficients = 3 * static_cast<size_t>(order) * order;
    std::vector<float> payloads(store.size() * floats);
    for (size_t i = 0; i < store.size(); ++i) {
        float* p = payloads.data() + i * floats;
        std::memcpy(p, store.payload_data(i), floats * sizeof(float));
        const float s = store.gradient_scale(i);
        for (size_t k = coefficients; k < floats; ++k) {
            p[k] *= s;
        }
    }
    return payloads;
}

CacheFileKey radiance_cache_key(const Scene& scene, float accuracy, int order) {
    CacheFileKey key;
    key.method = kRadianceMethodTag;
    key.payload_bytes = radiance_payload_floats(order) * sizeof(float);
    key.scene = scene_fingerprint(scene);
    key.scene_name = scene.path.string();
    key.accuracy = accuracy;
    return key;
}

}  // namespace rc
