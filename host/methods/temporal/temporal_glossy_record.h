// A glossy cache's record as temporal caching keeps it across frames, whatever its payload (the
// report's §3: "the method ... is similarly applicable to both caching techniques"; `--method rc
// --temporal`: SH coefficient vectors and their gradients; `--method sdrc --temporal`: the
// radiance of the L-tree's samples): the payload takes the place of the irradiance in the
// temporal weight (eqs. 9-12) and the temporal gradients (eqs. 18-23), as in temporal_record.h.
#pragma once

#include <cstddef>
#include <vector>

#include "methods/caching/record_store.h"
#include "methods/temporal/temporal_options.h"
#include "shared/radiance_cache.h"

namespace rc {

struct TemporalGlossyRecord {
    shared::Record record{};  // as last clamped
    RecordHostData host{};
    std::vector<float> payload;  // as computed: 3 channels of floats first, then anything else
    std::vector<float> next;     // estimated at created + 1 by reprojection
    shared::RcQuery site{};      // where it was computed (a replacement is computed there again)
    unsigned stream = 0;         // its random stream (a replacement draws the same)
    int created = 0;             // t_k
    int lifespan = 1;            // it serves frames created .. created + lifespan - 1
    bool site_moves = false;     // its own surface moves away by the next frame
    int successor = -1;          // the record computed in its place at created + lifespan, or -1
};

// A new glossy record's estimate at the next frame, from the reprojection of its samples.
struct CarriedGlossyRecord {
    shared::RcQuery site{};   // where it was computed
    unsigned stream = 0;      // its random stream
    std::vector<float> next;  // its payload estimated one frame later
    bool site_moves = false;  // the triangle the record lies on moves by then
};

// The relative change of a payload from `now` to `next`, whose first 3 x `per_channel` floats are
// its three channels: per channel |lambda_1 - lambda_0| / |lambda_0| (L2 norms), the largest over
// the channels whose |lambda_0| holds at least 1e-3 of the largest; infinite when lambda_0 is zero
// and lambda_1 is not. For a payload scaled by tau it is |tau - 1|, the report's eq. 7.
float glossy_temporal_change(const std::vector<float>& now, const std::vector<float>& next,
                             size_t per_channel);

// Record r's payload at `frame` (created <= frame < created + lifespan): held (none), moved by
// (next - payload)(t - t_0) (extrapolated, eqs. 18-20) or blended towards `successor`'s, reaching
// it at its frame (interpolated, eqs. 21-23; extrapolated when `successor` is null).
std::vector<float> glossy_temporal_payload(const TemporalGlossyRecord& r,
                                           const TemporalGlossyRecord* successor, int frame,
                                           TemporalGradients gradients);

}  // namespace rc
