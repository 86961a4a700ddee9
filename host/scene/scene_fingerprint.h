// A fingerprint of a scene for the files made from it (irradiance caches, irradiance vector
// grids): a file made for another scene is refused.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace rc {

// A fingerprint of the scene's world geometry, shading, materials and lights at its frame.
uint64_t scene_fingerprint(const Scene& scene);

}  // namespace rc
