// How fast a clip moves, for `--method auto`'s choice of temporal caching (docs/auto.md,
// "Clips"): from the scene's animation tracks, no rendering.
#pragma once

#include "scene/scene.h"

namespace rc {

// The largest motion between consecutive frames of first..last (at most 16 pairs, evenly
// spaced): the farthest any vertex, light or the camera's eye moves, over the diagonal of the
// scene's mesh at `first`. 0 for one frame or a scene without animation.
double clip_motion(const Scene& scene, int first, int last);

}  // namespace rc
