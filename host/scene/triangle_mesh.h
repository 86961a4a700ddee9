// Indexed triangle meshes on the host, with optional per-vertex normals and texture coordinates
// and an optional per-triangle material slot.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace rc {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;  // indices into positions (and normals, uvs)
    std::vector<glm::vec3> normals;     // per vertex; empty: flat (geometric) shading
    std::vector<glm::vec2> uvs;         // per vertex; empty: no texture coordinates
    std::vector<int> materials;         // per triangle, a slot its owner maps; empty: one slot

    size_t triangle_count() const { return triangles.size(); }
    // Appends `other`, offsetting its indices. Normals, uvs and material slots are kept when both
    // meshes have them, and dropped otherwise.
    void append(const TriangleMesh& other);
};

// Removes triangles of zero area (collinear or repeated vertices, decided in double precision);
// returns how many were removed. When `kept` is given it receives, for each remaining triangle,
// its index before the removal.
size_t drop_degenerate_triangles(TriangleMesh& mesh, std::vector<size_t>* kept = nullptr);

}  // namespace rc
