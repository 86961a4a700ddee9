// How fast a clip moves, for `--method auto`'s choice of temporal caching (docs/auto.md,
// "Clips"): from the scene's animation tracks, no rendering.
#pragma once

#include "scene/scene.h"

namespace rc {

// The largest motion between consecutive frames of first..last (at most 16 pairs, evenly
// spaced): the farthest any vertex or light moves, over the diagonal of the scene's mesh at
// `first`. 0 for one frame or a scene without animation. The camera does not count: its motion
// uncovers surfaces (which temporal caching covers with new records) but does not change the light
// a record holds, so a walkthrough of a still scene is a still clip for temporal caching.

double clip_motion(const Scene& scene, int first, int last);

}  // namespace rc
