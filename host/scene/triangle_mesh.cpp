#include "scene/triangle_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <unordered_set>

namespace rc {

void TriangleMesh::append(const TriangleMesh& other) {
    const bool keep_normals = (positions.empty() || !normals.empty()) && !other.normals.empty();
    const bool keep_uvs = (positions.empty() || !uvs.empty()) && !other.uvs.empty();
    const bool keep_materials =
        (triangles.empty() || !materials.empty()) && !other.materials.empty();
    const auto offset = static_cast<unsigned>(positions.size());
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    triangles.reserve(triangles.size() + other.triangles.size());
    for (const glm::uvec3& t : other.triangles) {
        triangles.push_back(t + glm::uvec3(offset));
    }
    if (keep_normals) {
        normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    } else {
        normals.clear();
    }
    if (keep_uvs) {
        uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
    } else {
        uvs.clear();
    }
    if (keep_materials) {
        materials.insert(materials.end(), other.materials.begin(), other.materials.end());
    } else {
        materials.clear();
    }
}

size_t drop_degenerate_triangles(TriangleMesh& mesh, std::vector<size_t>* kept) {
    std::vector<glm::uvec3> remaining;
    std::vector<int> remaining_materials;
    remaining.reserve(mesh.triangles.size());
    if (kept != nullptr) {
        kept->clear();
    }
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 a(mesh.positions[t.x]);
        const glm::dvec3 b(mesh.positions[t.y]);
        const glm::dvec3 c(mesh.positions[t.z]);
        const glm::dvec3 normal = glm::cross(b - a, c - a);
        if (normal.x == 0.0 && normal.y == 0.0 && normal.z == 0.0) {
            continue;
        }
        remaining.push_back(t);
        if (!mesh.materials.empty()) {
            remaining_materials.push_back(mesh.materials[i]);
        }
        if (kept != nullptr) {
            kept->push_back(i);
        }
    }
    const size_t dropped = mesh.triangles.size() - remaining.size();
    mesh.triangles = std::move(remaining);
    if (!mesh.materials.empty()) {
        mesh.materials = std::move(remaining_materials);
    }
    return dropped;
}

namespace {

// A triangle's vertex positions as bits, rotated so that the smallest vertex comes first: equal
// for two triangles exactly when they have bitwise the same vertices in the same cyclic order.
using TriangleKey = std::array<uint32_t, 9>;

TriangleKey triangle_key(const TriangleMesh& mesh, const glm::uvec3& t) {
    std::array<std::array<uint32_t, 3>, 3> v{};
    for (int i = 0; i < 3; ++i) {
        std::memcpy(v[i].data(), &mesh.positions[t[i]], sizeof(glm::vec3));
    }
    const int first = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
    TriangleKey key{};
    for (int i = 0; i < 3; ++i) {
        std::copy(v[(first + i) % 3].begin(), v[(first + i) % 3].end(), key.begin() + 3 * i);
    }
    return key;
}

struct TriangleKeyHash {
    size_t operator()(const TriangleKey& key) const {
        uint64_t h = 1469598103934665603ull;  // FNV-1a over the nine words
        for (uint32_t word : key) {
            h = (h ^ word) * 1099511628211ull;
        }
        return static_cast<size_t>(h);
    }
};

}  // namespace

size_t drop_repeated_triangles(TriangleMesh& mesh) {
    std::unordered_set<TriangleKey, TriangleKeyHash> seen;
    seen.reserve(mesh.triangles.size());
    size_t kept = 0;
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        if (!seen.insert(triangle_key(mesh, mesh.triangles[i])).second) {
            continue;
        }
        mesh.triangles[kept] = mesh.triangles[i];
        if (!mesh.materials.empty()) {
            mesh.materials[kept] = mesh.materials[i];
        }
        ++kept;
    }
    const size_t dropped = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    if (!mesh.materials.empty()) {
        mesh.materials.resize(kept);
    }
    return dropped;
}

bool is_planar_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const glm::dvec3 n = glm::cross(glm::dvec3(c) - glm::dvec3(a), glm::dvec3(d) - glm::dvec3(b));
    const double size =
        glm::length(glm::dvec3(c) - glm::dvec3(a)) + glm::length(glm::dvec3(d) - glm::dvec3(b));
    const double length = glm::length(n);
    return !(length > 0.0) ||
           std::abs(glm::dot(n / length, glm::dvec3(d) - glm::dvec3(a))) <= 1e-5 * size;
}

}  // namespace rc
