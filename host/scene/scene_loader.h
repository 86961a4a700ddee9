// Reads a scene file (docs/scene-format.md).
#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>

#include "scene/scene.h"
#include "scene/scene_files.h"

namespace rc {

// Loads the scene, reading it and its meshes and textures through `files`; any problem throws
// Error naming the file and the key or line. A scene without light is warned about (log_warning).
// A .gltf or .glb file is imported (scene/gltf_loader.h), `camera` naming its camera (empty: the
// first); a .pbrt file is imported (scene/pbrt_loader.h); a JSON or pbrt scene takes no camera
// name. With `environment`, the scene's environment is that radiance or lat-long map (added when
// the scene has none, replacing the one it has) before the lighting check.
// Whether `path` names a scene load_scene imports from another format (glTF or pbrt-v4).
bool is_imported_scene_path(const std::filesystem::path& path);

// An environment given from outside the scene (render --environment): a radiance, or the image
// of a lat-long map (read through the scene's files).
struct EnvironmentOverride {
    glm::vec3 radiance{1.0f};
    std::filesystem::path map;  // empty: the radiance
};

Scene load_scene(const std::filesystem::path& path, const SceneFiles& files = disk_files(),
                 const std::string& camera = "",
                 const std::optional<EnvironmentOverride>& environment = std::nullopt);

}  // namespace rc
