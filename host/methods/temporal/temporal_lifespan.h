// How long a record serves in temporal caching, whatever its payload (Gautron, Bouatouch and
// Pattanaik 2006, §4.2: the temporal weighting function, eqs. 9-12; §4.4 for interpolated
// gradients): from its relative change to the next frame (or its curvature), the user's temporal
// accuracy a^t and the longest lifespan delta t_max. The change itself is the payload's
// (temporal_record.h for irradiance, temporal_glossy_record.h for rc's and sdrc's records).
#pragma once

#include "methods/temporal/temporal_options.h"

namespace rc {

// How many frames a record with that change serves, counting its own: the temporal weight
// w^t(t) = 1 / (|tau - 1| (t - t_0)) (eq. 9) stays at least 1 / a^t (eq. 10) for
// t - t_0 <= a^t / |tau - 1|, and t - t_0 < delta t_max (eq. 12). A record whose own surface moves
// serves one frame.
int temporal_lifespan(float change, const TemporalOptions& options, bool site_moves);

// How many frames a record serves when the bound is its departure from the line towards its
// replacement (interpolated gradients, the report's eqs. 21-23 with a replacement at t_0 + L):
// for E(t) = E_0 + b (t - t_0) + c (t - t_0)^2 / 2 the line from E(t_0) to E(t_0 + L) departs
// from E by c (t - t_0)(t_0 + L - t) / 2, at most |c| L^2 / 8 (at t_0 + L / 2), which stays
// within a^t (eq. 10's bound on the relative error) for L <= sqrt(8 a^t / |c|); at most
// delta t_max (eq. 12), at least 1. A change linear in time (c = 0) serves delta t_max. A record
// whose own surface moves serves one frame.
int departure_lifespan(float curvature, const TemporalOptions& options, bool site_moves);

// `lifespan` of a record created at `frame` of a clip ending at `last_frame`, cut as
// temporal_lifespan_in_clip cuts it (`change`: the record's one-frame change).
int lifespan_in_clip(int lifespan, float change, const TemporalOptions& options, int frame,
                     int last_frame);

// temporal_lifespan of a record created at `frame` of a clip ending at `last_frame`, where with
// interpolated gradients a changing record that would outlive the clip expires at its last frame
// instead, so that it is replaced there and the frames before blend towards the replacement
// rather than extrapolate the record's one-frame change over several (a record that sees no
// change keeps its value either way).
int temporal_lifespan_in_clip(float change, const TemporalOptions& options, bool site_moves,
                              int frame, int last_frame);

}  // namespace rc
