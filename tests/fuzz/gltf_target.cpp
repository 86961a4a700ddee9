// Fuzz target: a glTF 2.0 file (JSON or binary .glb) with the buffers and images it names, read
// through memory and imported into a scene (scene/gltf_loader.h).
#include "fuzz_targets.h"
#include "scene/gltf_loader.h"
#include "scene/scene_files.h"
#include "util/error.h"
#include "util/log.h"

namespace rc::fuzz {

int gltf(const uint8_t* data, size_t size) {
    set_quiet(true);
    MemoryFiles files;
    for (auto& [name, bytes] : split_files(data, size, "scene.gltf")) {
        files.add(name, std::move(bytes));
    }
    try {
        load_gltf_scene("scene.gltf", files);
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace rc::fuzz
