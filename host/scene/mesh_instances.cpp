#include "scene/mesh_instances.h"

#include <cstring>
#include <string_view>
#include <unordered_map>

namespace rc {
namespace {

// The bytes of a vector's elements.
template <typename T>
std::string_view bytes_of(const std::vector<T>& values) {
    return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

// A hash of the mesh's contents (equal meshes hash equal; collisions are compared in full).
size_t mesh_hash(const TriangleMesh& mesh) {
    const std::hash<std::string_view> hash;
    size_t h = hash(bytes_of(mesh.positions));
    for (const size_t part : {hash(bytes_of(mesh.triangles)), hash(bytes_of(mesh.normals)),
                              hash(bytes_of(mesh.uvs)), hash(bytes_of(mesh.materials))}) {
        h = h * 1000003u ^ part;
    }
    return h;
}

bool same_bytes(std::string_view a, std::string_view b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size()) == 0);
}

bool same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
    return same_bytes(bytes_of(a.positions), bytes_of(b.positions)) &&
           same_bytes(bytes_of(a.triangles), bytes_of(b.triangles)) &&
           same_bytes(bytes_of(a.normals), bytes_of(b.normals)) &&
           same_bytes(bytes_of(a.uvs), bytes_of(b.uvs)) &&
           same_bytes(bytes_of(a.materials), bytes_of(b.materials));
}

}  // namespace

std::vector<size_t> first_shape_with_mesh(const std::vector<Shape>& shapes) {
    std::vector<size_t> first(shapes.size());
    std::unordered_multimap<size_t, size_t> by_hash;  // hash -> a first shape with it
    for (size_t s = 0; s < shapes.size(); ++s) {
        const size_t h = mesh_hash(shapes[s].mesh);
        first[s] = s;
        const auto [begin, end] = by_hash.equal_range(h);
        for (auto it = begin; it != end; ++it) {
            if (same_mesh(shapes[it->second].mesh, shapes[s].mesh)) {
                first[s] = it->second;
                break;
            }
        }
        if (first[s] == s) {
            by_hash.emplace(h, s);
        }
    }
    return first;
}

}  // namespace rc
