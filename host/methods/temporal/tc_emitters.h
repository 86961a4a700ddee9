// A frame's emitters as temporal caching's unshadowed-light estimate reads them
// (kernels/shared/temporal.h, TcEmitter): every point, spot, distant and environment light, and
// every triangle of every area light, in world space at the scene's current frame. The list of
// two frames of one scene has the same entries in the same order.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "shared/temporal.h"

namespace rc {

std::vector<shared::TcEmitter> unshadowed_emitters(const Scene& scene);

}  // namespace rc
