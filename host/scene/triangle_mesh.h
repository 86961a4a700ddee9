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

// Removes each triangle whose vertex positions repeat, bitwise and in the same cyclic order (the
// same oriented surface), an earlier triangle's: the earlier one is kept with its material,
// normals and texture coordinates. Coincident copies add no surface, but a ray through them must
// test every copy (no BVH can split them). Returns how many were removed.
size_t drop_repeated_triangles(TriangleMesh& mesh);

// Whether the quad a b c d lies in one plane (to a relative 1e-5 of its size): then its two
// triangles a b c, a c d are exactly the quad (pbrt's bilinear patch, a PLY quad). A degenerate
// quad counts as planar (its triangles are dropped or flat).
bool is_planar_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);

}  // namespace rc
