// Temporal caching's command-line options (`--method ic --temporal`; docs/temporal-caching.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "util/cli.h"
#include "util/option_table.h"

namespace rc {

// How a record's value changes over the frames it serves (the report's §4.4): held
// (none), extrapolated from its own reprojected estimate of the next frame (eqs. 18-20, one
// pass), or interpolated towards the record that replaces it (eqs. 21-23, two passes).
enum class TemporalGradients { kNone, kExtrapolated, kInterpolated };

// What bounds a first-level record's lifespan: its estimated change since its creation (the
// report's eqs. 9-12), or, with interpolated gradients, its estimated departure from the line
// towards its replacement (the curvature of its change, from a second reprojection two frames
// ahead; docs/temporal-caching.md, "Lifespans by departure from the line").
enum class TemporalLifespan { kChange, kDeparture };

struct TemporalOptions {
    bool enabled = false;
    TemporalGradients gradients = TemporalGradients::kInterpolated;
    TemporalLifespan lifespan = TemporalLifespan::kChange;
    float accuracy = 0.02f;  // a^t of eq. 10 (the report's §6 uses 0.05; docs/temporal-caching.md)
    int max_frames = 20;     // delta t_max of eq. 12 (the report's §6: 20 frames)
    // --temporal-max-frames given: it bounds every record. Not given, a record created while
    // nothing in the scene moves or changes light (only the camera may move: a walkthrough) sees
    // no change (E_1 = E_0) and serves until something does (docs/temporal-caching.md).
    bool max_frames_given = false;
    int hole_passes = 4;  // 3 x 3 hole-filling passes of the reprojection (§4.3)
    // Hemisphere hits on triangles that move before the next frame get deeper-level records
    // (which serve that frame only) when true; path-trace the diffuse lobe beyond when false.
    bool cache_moving_hits = false;
};

// --temporal and the --temporal-* options.
OptionTable<TemporalOptions> temporal_option_table();

// Error (exit status 2) naming the option: the --temporal-* options need --temporal, and
// lifespans by departure need interpolated gradients. Sets max_frames_given.
void check_temporal_options(TemporalOptions& options, const ParsedArguments& arguments);

std::string temporal_gradients_name(TemporalGradients gradients);
std::string temporal_lifespan_name(TemporalLifespan lifespan);

// With --temporal the records live across frames, not in cache files: Error (exit status 2)
// naming `options` (the cache-file options of the method) when `given`.
void refuse_cache_files_with_temporal(bool given, const std::string& options);

// Temporal caching renders --spp camera samples a frame, not by time: Error (exit status 2)
// naming --time when `options` are enabled and `time` > 0.
void refuse_time_with_temporal(const TemporalOptions& options, double time);

// Temporal caching renders on one device: Error (exit status 2) when a frame has `devices` > 1.
void refuse_temporal_on_several_devices(size_t devices);

}  // namespace rc
