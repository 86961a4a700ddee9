// Indexed triangle meshes on the host.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace rc {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;  // indices into positions

    size_t triangle_count() const { return triangles.size(); }
    // Appends `other`, offsetting its indices.
    void append(const TriangleMesh& other);
};

// Removes triangles of zero area (collinear or repeated vertices, decided in double precision);
// returns how many were removed. When `kept` is given it receives, for each remaining triangle,
// its index before the removal.
size_t drop_degenerate_triangles(TriangleMesh& mesh, std::vector<size_t>* kept = nullptr);

}  // namespace rc
