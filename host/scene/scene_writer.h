// Writes a loaded scene in radcache's scene format (docs/scene-format.md): the JSON file, each
// shape's mesh as a Wavefront OBJ in OUT_meshes/ beside it (object space, with its transform as a
// matrix step), and each texture that came from inside a glTF file in OUT_textures/. Every number
// is written so that it reads back to the same float: rendering the written scene gives the image
// of the loaded one (`radcache convert`).
#pragma once

#include <filesystem>

#include "scene/scene.h"

namespace rc {

// Error naming the shape for what the format cannot hold (a shape with several material slots).
void write_scene(const Scene& scene, const std::filesystem::path& json);

}  // namespace rc
