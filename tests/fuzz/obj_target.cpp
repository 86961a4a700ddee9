// Fuzz target: an OBJ file and the MTL libraries it names, read through memory.
#include "fuzz_targets.h"
#include "scene/obj_loader.h"

namespace rc::fuzz {

int obj(const uint8_t* data, size_t size) {
    return load_from_memory(data, size, "mesh.obj",
                            [](const std::string& path, const SceneFiles& files) {
                                ObjData loaded = load_obj(path, files);
                                drop_degenerate_triangles(loaded.mesh);
                            });
}

}  // namespace rc::fuzz
