// Reads a scene file (docs/scene-format.md).
#pragma once

#include <filesystem>

#include "scene/scene.h"

namespace rc {

// Loads the scene; any problem throws Error naming the file and the key or line.
Scene load_scene(const std::filesystem::path& path);

}  // namespace rc
