#include "scene/scene_fingerprint.h"

#include <OpenImageIO/hash.h>

#include <vector>

namespace rc {
namespace {

template <class T>
uint64_t hash_bytes(const std::vector<T>& values, uint64_t seed) {
    const uint64_t h = OIIO::farmhash::Fingerprint64(reinterpret_cast<const char*>(values.data()),
                                                     values.size() * sizeof(T));
    return OIIO::farmhash::Fingerprint(OIIO::farmhash::Uint128(seed, h));
}

}  // namespace

uint64_t scene_fingerprint(const Scene& scene) {
    uint64_t h = 0x5243534345ull;
    h = hash_bytes(scene.mesh.positions, h);
    h = hash_bytes(scene.mesh.triangles, h);
    h = hash_bytes(scene.shading, h);
    h = hash_bytes(scene.normals, h);
    std::vector<shared::Material> materials;
    for (const Material& m : scene.materials) {
        materials.push_back(to_device(m));
    }
    h = hash_bytes(materials, h);
    h = hash_bytes(scene.lights.lights, h);
    return h;
}

}  // namespace rc
