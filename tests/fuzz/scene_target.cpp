// Fuzz target: a scene file and the files it names (meshes, MTL libraries, textures), read
// through memory, loaded, posed at its last frame, and its BVH built in each layout (the issue's
// Embree assertion came from world positions that overflow).
#include "bvh/bvh.h"
#include "fuzz_targets.h"
#include "scene/scene_files.h"
#include "scene/scene_loader.h"
#include "util/error.h"

namespace rc::fuzz {

int scene(const uint8_t* data, size_t size) {
    MemoryFiles files;
    for (auto& [name, bytes] : split_files(data, size, "scene.json")) {
        files.add(name, std::move(bytes));
    }
    try {
        Scene loaded = load_scene("scene.json", files);
        if (loaded.animation.frame_end != loaded.animation.frame_start) {
            loaded.set_frame(loaded.animation.frame_end);
        }
        if (loaded.mesh.triangle_count() <= 50000) {
            for (const BvhLayout layout : kBvhLayouts) {
                build_bvh(loaded.mesh, layout);
            }
        }
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace rc::fuzz
