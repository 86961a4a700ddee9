#include "methods/temporal/temporal_record.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rc {
namespace {

shared::float4 lerp4(const shared::float4& a, const shared::float4& b, float f) {
    return {a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f, a.z + (b.z - a.z) * f, 0.0f};
}

// a + (b - a) f for E and both gradients; the occluder a's.
shared::IrradiancePayload blend(const shared::IrradiancePayload& a,
                                const shared::IrradiancePayload& b, float f) {
    shared::IrradiancePayload p = a;
    p.irradiance = lerp4(a.irradiance, b.irradiance, f);
    p.irradiance.x = std::max(0.0f, p.irradiance.x);
    p.irradiance.y = std::max(0.0f, p.irradiance.y);
    p.irradiance.z = std::max(0.0f, p.irradiance.z);
    p.rotation_r = lerp4(a.rotation_r, b.rotation_r, f);
    p.rotation_g = lerp4(a.rotation_g, b.rotation_g, f);
    p.rotation_b = lerp4(a.rotation_b, b.rotation_b, f);
    p.translation_r = lerp4(a.translation_r, b.translation_r, f);
    p.translation_g = lerp4(a.translation_g, b.translation_g, f);
    p.translation_b = lerp4(a.translation_b, b.translation_b, f);
    return p;
}

}  // namespace

float temporal_change(const shared::IrradiancePayload& now, const shared::IrradiancePayload& next) {
    const float e0[3] = {now.irradiance.x, now.irradiance.y, now.irradiance.z};
    const float e1[3] = {next.irradiance.x, next.irradiance.y, next.irradiance.z};
    const float largest = std::max({e0[0], e0[1], e0[2]});
    if (!(largest > 0.0f)) {
        return std::max({e1[0], e1[1], e1[2]}) > 0.0f ? std::numeric_limits<float>::infinity()
                                                      : 0.0f;
    }
    float change = 0.0f;
    for (int c = 0; c < 3; ++c) {
        if (e0[c] >= 1e-3f * largest) {
            change = std::max(change, std::fabs(e1[c] / e0[c] - 1.0f));
        }
    }
    return std::isfinite(change) ? change : std::numeric_limits<float>::infinity();
}

float temporal_curvature(const shared::IrradiancePayload& now,
                         const shared::IrradiancePayload& next,
                         const shared::IrradiancePayload& ahead) {
    const float e0[3] = {now.irradiance.x, now.irradiance.y, now.irradiance.z};
    const float e1[3] = {next.irradiance.x, next.irradiance.y, next.irradiance.z};
    const float e2[3] = {ahead.irradiance.x, ahead.irradiance.y, ahead.irradiance.z};
    const float largest = std::max({e0[0], e0[1], e0[2]});
    if (!(largest > 0.0f)) {
        return std::max({e1[0], e1[1], e1[2], e2[0], e2[1], e2[2]}) > 0.0f
                   ? std::numeric_limits<float>::infinity()
                   : 0.0f;
    }
    float curvature = 0.0f;
    for (int c = 0; c < 3; ++c) {
        if (e0[c] >= 1e-3f * largest) {
            // The second difference in double: E_2 - 2 E_1 + E_0 cancels.
            const double second = static_cast<double>(e2[c]) - 2.0 * e1[c] + e0[c];
            curvature = std::max(curvature, static_cast<float>(std::fabs(second) / e0[c]));
        }
    }
    return std::isfinite(curvature) ? curvature : std::numeric_limits<float>::infinity();
}

shared::IrradiancePayload temporal_payload(const TemporalRecord& r, const TemporalRecord* successor,
                                           int frame, TemporalGradients gradients) {
    const float elapsed = static_cast<float>(frame - r.created);
    const shared::IrradiancePayload& base = r.computed.payload;
    if (gradients == TemporalGradients::kNone || elapsed == 0.0f) {
        return base;
    }
    if (gradients == TemporalGradients::kInterpolated && successor != nullptr) {
        const float span = static_cast<float>(successor->created - r.created);
        return blend(base, successor->computed.payload, elapsed / span);
    }
    return blend(base, r.next, elapsed);
}

}  // namespace rc
