// A first-level irradiance record as temporal caching keeps it across frames (the report's §4):
// where and when it was computed, how long it serves (its lifespan, from the temporal weighting
// function), its value estimated one frame later (reprojection) and the record that replaces it,
// from which its value at any frame it serves follows (temporal gradients).
#pragma once

#include "methods/caching/cache_pipeline.h"
#include "methods/caching/irradiance_records.h"
#include "methods/temporal/temporal_lifespan.h"
#include "methods/temporal/temporal_options.h"

namespace rc {

struct TemporalRecord {
    ComputedRecord computed;  // as computed (record and host data as last clamped)
    RecordSite site;          // where it was computed (a replacement is computed there again)
    int created = 0;          // t_k
    int lifespan = 1;         // it serves frames created .. created + lifespan - 1
    shared::IrradiancePayload next{};  // estimated at created + 1 (TemporalReprojection)
    bool site_moves = false;           // its own surface moves away by the next frame
    int successor = -1;  // the record computed in its place at created + lifespan, or -1
    // Created while nothing in the scene moved or changed light to the next frame (without
    // --temporal-max-frames): it serves until a frame from which something does.
    bool until_motion = false;
};

// The largest relative change over the RGB channels from E_0 (the record's irradiance) to E_1
// (its estimate one frame later): |tau - 1| of the report's eq. 7 with tau = E_1 / E_0, over the
// channels holding at least 1e-3 of E_0's largest; infinite when E_0 is black and E_1 is not.
float temporal_change(const shared::IrradiancePayload& now, const shared::IrradiancePayload& next);

// The curvature of a record's irradiance over its first frames, relative: the largest over the
// RGB channels holding at least 1e-3 of E_0's largest of |E_2 - 2 E_1 + E_0| / E_0 (the second
// difference of E at t_0, t_0 + 1, t_0 + 2: E_1 and E_2 reprojected one and two frames ahead);
// infinite when E_0 is black and E_1 or E_2 is not.
float temporal_curvature(const shared::IrradiancePayload& now,
                         const shared::IrradiancePayload& next,
                         const shared::IrradiancePayload& ahead);

// Record r's payload at `frame` (created <= frame < created + lifespan): with `successor` (the
// record replacing it; may be null) and the chosen temporal gradients, E, grad_r and grad_t of
// eq. 17 with the extrapolated (eqs. 18-20) or interpolated (eqs. 21-23) temporal gradients; the
// irradiance never negative; the occluder the record's own.
shared::IrradiancePayload temporal_payload(const TemporalRecord& r, const TemporalRecord* successor,
                                           int frame, TemporalGradients gradients);

}  // namespace rc
