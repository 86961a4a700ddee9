#include "methods/temporal/temporal_lifespan.h"

#include <algorithm>
#include <cmath>

namespace rc {

int temporal_lifespan(float change, const TemporalOptions& options, bool site_moves) {
    if (site_moves) {
        return 1;
    }
    if (!(change > 0.0f)) {
        return options.max_frames;
    }
    const double frames = std::floor(static_cast<double>(options.accuracy) / change);
    return static_cast<int>(std::min<double>(options.max_frames, 1.0 + frames));
}

int departure_lifespan(float curvature, const TemporalOptions& options, bool site_moves) {
    if (site_moves) {
        return 1;
    }
    if (!(curvature > 0.0f)) {
        return options.max_frames;
    }
    const double frames =
        std::floor(std::sqrt(8.0 * static_cast<double>(options.accuracy) / curvature));
    return static_cast<int>(std::clamp<double>(frames, 1.0, options.max_frames));
}

int lifespan_in_clip(int lifespan, float change, const TemporalOptions& options, int frame,
                     int last_frame) {
    if (options.gradients == TemporalGradients::kInterpolated && change > 0.0f &&
        frame < last_frame && frame + lifespan > last_frame) {
        return last_frame - frame;
    }
    return lifespan;
}

int temporal_lifespan_in_clip(float change, const TemporalOptions& options, bool site_moves,
                              int frame, int last_frame) {
    return lifespan_in_clip(temporal_lifespan(change, options, site_moves), change, options, frame,
                            last_frame);
}

}  // namespace rc
