#include "methods/decomposition/triangle_split.h"

#include <glm/geometric.hpp>
#include <string>

#include "util/error.h"
#include "util/glm_helpers.h"

namespace rc {
namespace {

// A triangle waiting to be split, and the node that stands for it.
struct Pending {
    glm::vec3 a, b, c;
    uint32_t node;
};

// The plane through m and r, perpendicular to the triangle (p, q, r), with p on its side >= 0.
shared::float4 splitting_plane(const glm::vec3& p, const glm::vec3& q, const glm::vec3& r,
                               const glm::vec3& m) {
    const glm::vec3 normal = glm::cross(q - p, r - p);
    glm::vec3 across = glm::cross(normal, r - m);
    if (glm::dot(across, p - m) < 0.0f) {
        across = -across;
    }
    return shared::float4{across.x, across.y, across.z, -glm::dot(across, m)};
}

shared::SplitNode leaf_node(uint32_t triangle) {
    shared::SplitNode n{};
    n.children = -1;
    n.triangle = static_cast<int>(triangle);
    return n;
}

void check_count(size_t count, size_t max_triangles, float alpha, size_t scene_triangles) {
    if (count > max_triangles) {
        throw Error("--alpha " + std::to_string(alpha) +
                        ": the near field would split the scene's " +
                        std::to_string(scene_triangles) + " triangles into more than " +
                        std::to_string(max_triangles) + " (take a larger --alpha)",
                    kExitUsage);
    }
}

}  // namespace

TriangleSplit split_triangle_tree(const TriangleMesh& mesh, float alpha, size_t max_triangles) {
    TriangleSplit out;
    std::vector<Pending> stack;
    const float limit = alpha * alpha;
    for (size_t primitive = 0; primitive < mesh.triangles.size(); ++primitive) {
        const glm::uvec3& t = mesh.triangles[primitive];
        out.roots.push_back(static_cast<uint32_t>(out.nodes.size()));
        out.nodes.emplace_back();
        stack.push_back(
            {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z], out.roots.back()});
        while (!stack.empty()) {
            const Pending c = stack.back();
            stack.pop_back();
            // Edge k runs from corner k to corner k + 1; split the longest at its midpoint.
            const glm::vec3 corners[3] = {c.a, c.b, c.c};
            float longest = 0.0f;
            int edge = 0;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 d = corners[(k + 1) % 3] - corners[k];
                const float length2 = glm::dot(d, d);
                if (length2 > longest) {
                    longest = length2;
                    edge = k;
                }
            }
            if (longest <= limit) {
                out.nodes[c.node] = leaf_node(static_cast<uint32_t>(out.triangles.size()));
                shared::NearTriangle split{float4_of(c.a), float4_of(c.b), float4_of(c.c)};
                split.primitive = static_cast<uint32_t>(primitive);
                out.triangles.push_back(split);
                check_count(out.triangles.size(), max_triangles, alpha, mesh.triangles.size());
                continue;
            }
            const glm::vec3 p = corners[edge];
            const glm::vec3 q = corners[(edge + 1) % 3];
            const glm::vec3 r = corners[(edge + 2) % 3];
            const glm::vec3 m = 0.5f * (p + q);
            // Child `children` is (p, m, r), on the plane's side >= 0; `children` + 1 is (m, q, r).
            const uint32_t children = static_cast<uint32_t>(out.nodes.size());
            out.nodes[c.node].plane = splitting_plane(p, q, r, m);
            out.nodes[c.node].children = static_cast<int>(children);
            out.nodes[c.node].triangle = -1;
            out.nodes.emplace_back();
            out.nodes.emplace_back();
            // (p, m, r) and (m, q, r) keep the winding of (p, q, r); the second is taken first.
            stack.push_back({p, m, r, children});
            stack.push_back({m, q, r, children + 1});
        }
    }
    return out;
}

std::vector<shared::NearTriangle> split_triangles(const TriangleMesh& mesh, float alpha,
                                                  size_t max_triangles) {
    return split_triangle_tree(mesh, alpha, max_triangles).triangles;
}

uint32_t split_triangle_of(const TriangleSplit& split, uint32_t primitive, const glm::vec3& x) {
    const shared::SplitNode* node = &split.nodes[split.roots[primitive]];
    while (node->children >= 0) {
        const float side =
            node->plane.x * x.x + node->plane.y * x.y + node->plane.z * x.z + node->plane.w;
        node = &split.nodes[static_cast<size_t>(node->children) + (side >= 0.0f ? 0 : 1)];
    }
    return static_cast<uint32_t>(node->triangle);
}

}  // namespace rc
