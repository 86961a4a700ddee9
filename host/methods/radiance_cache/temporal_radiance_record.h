// A radiance record as temporal caching keeps it across frames (`--method rc --temporal`; the
// report's §3: "the method ... is similarly applicable to both caching techniques"): the record's
// SH coefficient vectors and their translational gradients take the place of the irradiance and
// its gradients in the temporal weight and the temporal gradients (temporal_record.h).
#pragma once

#include <vector>

#include "methods/records/record_store.h"
#include "methods/temporal/temporal_options.h"
#include "shared/radiance_cache.h"

namespace rc {

struct TemporalRadianceRecord {
    shared::Record record{};  // as last clamped
    RecordHostData host{};
    std::vector<float> payload;  // as computed (radiance_records.h: coefficients, gradients)
    std::vector<float> next;     // estimated at created + 1 (TcRadianceReprojection)
    shared::RcQuery site{};      // where it was computed (a replacement is computed there again)
    unsigned stream = 0;         // its random stream (a replacement draws the same)
    int created = 0;             // t_k
    int lifespan = 1;            // it serves frames created .. created + lifespan - 1
    bool site_moves = false;     // its own surface moves away by the next frame
    int successor = -1;          // the record computed in its place at created + lifespan, or -1
};

// The relative change of a radiance record's incoming radiance from `now` to `next` (payloads of
// order n): per channel |lambda_1 - lambda_0| / |lambda_0| over the coefficient vectors (L2 norm,
// by Parseval the relative L2 change of the projected radiance over the hemisphere), the largest
// over the channels whose |lambda_0| holds at least 1e-3 of the largest; infinite when lambda_0 is
// zero and lambda_1 is not. For radiance scaled by tau it is |tau - 1|, the report's eq. 7.
float radiance_temporal_change(const std::vector<float>& now, const std::vector<float>& next,
                               int order);

// Record r's payload at `frame` (created <= frame < created + lifespan): its coefficients and
// gradients held (none), moved by (next - payload)(t - t_0) (extrapolated, eqs. 18-20) or blended
// towards `successor`'s, reaching them at its frame (interpolated, eqs. 21-23; extrapolated when
// `successor` is null).
std::vector<float> radiance_temporal_payload(const TemporalRadianceRecord& r,
                                             const TemporalRadianceRecord* successor, int frame,
                                             TemporalGradients gradients);

}  // namespace rc
