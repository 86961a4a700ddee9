#include "methods/temporal/temporal_glossy_record.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rc {

float glossy_temporal_change(const std::vector<float>& now, const std::vector<float>& next,
                             size_t per_channel) {
    double norm[3] = {0.0, 0.0, 0.0};
    double difference[3] = {0.0, 0.0, 0.0};
    for (size_t c = 0; c < 3; ++c) {
        for (size_t k = c * per_channel; k < (c + 1) * per_channel; ++k) {
            const double d = static_cast<double>(next[k]) - now[k];
            norm[c] += static_cast<double>(now[k]) * now[k];
            difference[c] += d * d;
        }
    }
    const double largest = std::max({norm[0], norm[1], norm[2]});
    if (!(largest > 0.0)) {
        return std::max({difference[0], difference[1], difference[2]}) > 0.0
                   ? std::numeric_limits<float>::infinity()
                   : 0.0f;
    }
    double change = 0.0;
    for (int c = 0; c < 3; ++c) {
        if (norm[c] >= 1e-6 * largest) {  // |lambda_c| >= 1e-3 |lambda|_max
            change = std::max(change, std::sqrt(difference[c] / norm[c]));
        }
    }
    return std::isfinite(change) ? static_cast<float>(change)
                                 : std::numeric_limits<float>::infinity();
}

std::vector<float> glossy_temporal_payload(const TemporalGlossyRecord& r,
                                           const TemporalGlossyRecord* successor, int frame,
                                           TemporalGradients gradients) {
    const float elapsed = static_cast<float>(frame - r.created);
    if (gradients == TemporalGradients::kNone || elapsed == 0.0f) {
        return r.payload;
    }
    const bool towards_successor =
        gradients == TemporalGradients::kInterpolated && successor != nullptr;
    const std::vector<float>& target = towards_successor ? successor->payload : r.next;
    const float f =
        towards_successor ? elapsed / static_cast<float>(successor->created - r.created) : elapsed;
    std::vector<float> payload(r.payload.size());
    for (size_t k = 0; k < payload.size(); ++k) {
        payload[k] = r.payload[k] + (target[k] - r.payload[k]) * f;
    }
    return payload;
}

}  // namespace rc
