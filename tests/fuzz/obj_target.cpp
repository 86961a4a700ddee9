// Fuzz target: an OBJ file and the MTL libraries it names, read through memory.
#include "fuzz_targets.h"
#include "scene/obj_loader.h"
#include "scene/scene_files.h"
#include "util/error.h"

namespace rc::fuzz {

int obj(const uint8_t* data, size_t size) {
    MemoryFiles files;
    for (auto& [name, bytes] : split_files(data, size, "mesh.obj")) {
        files.add(name, std::move(bytes));
    }
    try {
        ObjData loaded = load_obj("mesh.obj", files);
        drop_degenerate_triangles(loaded.mesh);
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace rc::fuzz
