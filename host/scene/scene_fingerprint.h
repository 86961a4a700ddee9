// A fingerprint of what a scene renders, so files made for one scene (irradiance cache records,
// irradiance vector grids) are refused for another.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace rc {

// A fingerprint of the scene's world geometry, shading, materials and lights at its frame.
uint64_t scene_fingerprint(const Scene& scene);

}  // namespace rc
