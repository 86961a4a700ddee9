// Fuzz target: a scene file and the files it names (meshes, MTL libraries, textures), read
// through memory, loaded, posed at its last frame, and its BVH built in each layout (the issue's
// Embree assertion came from world positions that overflow).
#include "bvh/bvh.h"
#include "fuzz_targets.h"
#include "scene/scene_loader.h"

namespace rc::fuzz {

int scene(const uint8_t* data, size_t size) {
    return load_from_memory(data, size, "scene.json",
                            [](const std::string& path, const SceneFiles& files) {
                                Scene loaded = load_scene(path, files);
                                if (loaded.animation.frame_end != loaded.animation.frame_start) {
                                    loaded.set_frame(loaded.animation.frame_end);
                                }
                                if (loaded.mesh.triangle_count() <= 50000) {
                                    for (const BvhLayout layout : kBvhLayouts) {
                                        build_bvh(loaded.mesh, layout);
                                    }
                                }
                            });
}

}  // namespace rc::fuzz
