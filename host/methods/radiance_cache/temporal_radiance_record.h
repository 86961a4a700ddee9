// A radiance record as temporal caching keeps it across frames (`--method rc --temporal`; the
// report's §3: "the method ... is similarly applicable to both caching techniques"): the record's
// SH coefficient vectors and their translational gradients (radiance_records.h) are the payload of
// a glossy record (temporal/temporal_glossy_record.h), in the temporal weight and the temporal
// gradients.
#pragma once

#include <cstddef>
#include <vector>

#include "methods/temporal/temporal_glossy_record.h"

namespace rc {

using TemporalRadianceRecord = TemporalGlossyRecord;

// The relative change of a radiance record's incoming radiance from `now` to `next` (payloads of
// order n): glossy_temporal_change over the n^2 coefficients of each channel, by Parseval the
// relative L2 change of the projected radiance over the hemisphere.
inline float radiance_temporal_change(const std::vector<float>& now, const std::vector<float>& next,
                                      int order) {
    return glossy_temporal_change(now, next, static_cast<size_t>(order) * order);
}

}  // namespace rc
