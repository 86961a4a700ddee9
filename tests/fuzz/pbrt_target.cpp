// Fuzz target: a pbrt-v4 scene with the files it includes, its PLY meshes and its textures, read
// through memory and imported into a scene (scene/pbrt_loader.h): the tokenizer, the directive
// parser, the graphics state and Assimp's PLY reader.
#include "fuzz_targets.h"
#include "scene/pbrt_loader.h"
#include "scene/scene_files.h"
#include "util/error.h"
#include "util/log.h"

namespace rc::fuzz {

int pbrt(const uint8_t* data, size_t size) {
    set_quiet(true);
    MemoryFiles files;
    for (auto& [name, bytes] : split_files(data, size, "scene.pbrt")) {
        files.add(name, std::move(bytes));
    }
    try {
        load_pbrt_scene("scene.pbrt", files);
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace rc::fuzz
