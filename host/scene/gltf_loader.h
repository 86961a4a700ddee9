// Reads a glTF 2.0 scene (.gltf with its buffers and images, or .glb) through tinygltf into a
// radcache scene: meshes with their node transforms, the camera, metallic-roughness materials
// mapped to ours, base-colour textures, emissive materials as area lights, KHR_lights_punctual
// point and spot lights. What it cannot honour is warned about once per feature; what makes the
// file unreadable is an Error naming the file. Mapping: docs/importing.md#gltf-20-import.
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene.h"
#include "scene/scene_files.h"

namespace rc {

// Whether `path` names a glTF scene (.gltf or .glb, any case).
bool is_gltf_path(const std::filesystem::path& path);

// Loads the glTF file; `camera` picks a camera by its name or its node's name (empty: the first
// met in the scene's node order). The scene is posed at frame 0.
Scene load_gltf_scene(const std::filesystem::path& path, const SceneFiles& files,
                      const std::string& camera = "");

}  // namespace rc
