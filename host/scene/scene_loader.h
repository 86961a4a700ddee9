// Reads a scene file (docs/scene-format.md).
#pragma once

#include <filesystem>

#include "scene/scene.h"
#include "scene/scene_files.h"

namespace rc {

// Loads the scene, reading it and its meshes and textures through `files`; any problem throws
// Error naming the file and the key or line. A scene without light is warned about (log_warning).
// A .gltf or .glb file is imported (scene/gltf_loader.h), `camera` naming its camera (empty: the
// first); a JSON scene takes no camera name.
Scene load_scene(const std::filesystem::path& path, const SceneFiles& files = disk_files(),
                 const std::string& camera = "");

}  // namespace rc
