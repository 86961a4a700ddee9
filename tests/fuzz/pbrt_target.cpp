// Fuzz target: a pbrt-v4 scene with the files it includes, its PLY meshes and its textures, read
// through memory and imported into a scene (scene/pbrt_loader.h): the tokenizer, the directive
// parser, the graphics state and Assimp's PLY reader.
#include "fuzz_targets.h"
#include "scene/pbrt_loader.h"
#include "util/log.h"

namespace rc::fuzz {

int pbrt(const uint8_t* data, size_t size) {
    set_quiet(true);
    return load_from_memory(
        data, size, "scene.pbrt",
        [](const std::string& path, const SceneFiles& files) { load_pbrt_scene(path, files); });
}

}  // namespace rc::fuzz
