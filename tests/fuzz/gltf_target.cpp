// Fuzz target: a glTF 2.0 file (JSON or binary .glb) with the buffers and images it names, read
// through memory and imported into a scene (scene/gltf_loader.h).
#include "fuzz_targets.h"
#include "scene/gltf_loader.h"
#include "util/log.h"

namespace rc::fuzz {

int gltf(const uint8_t* data, size_t size) {
    set_quiet(true);
    return load_from_memory(
        data, size, "scene.gltf",
        [](const std::string& path, const SceneFiles& files) { load_gltf_scene(path, files); });
}

}  // namespace rc::fuzz
