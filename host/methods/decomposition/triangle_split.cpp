#include "methods/decomposition/triangle_split.h"

#include <glm/geometric.hpp>
#include <string>

#include "util/error.h"
#include "util/glm_helpers.h"

namespace rc {
namespace {

struct Corners {
    glm::vec3 a, b, c;
};

}  // namespace

std::vector<shared::NearTriangle> split_triangles(const TriangleMesh& mesh, float alpha,
                                                  size_t max_triangles) {
    std::vector<shared::NearTriangle> out;
    std::vector<Corners> stack;
    const float limit = alpha * alpha;
    for (size_t primitive = 0; primitive < mesh.triangles.size(); ++primitive) {
        const glm::uvec3& t = mesh.triangles[primitive];
        stack.push_back({mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]});
        while (!stack.empty()) {
            const Corners c = stack.back();
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
                shared::NearTriangle split{float4_of(c.a), float4_of(c.b), float4_of(c.c)};
                split.primitive = static_cast<uint32_t>(primitive);
                out.push_back(split);
                if (out.size() > max_triangles) {
                    throw Error("--alpha " + std::to_string(alpha) +
                                    ": the near field would split the scene's " +
                                    std::to_string(mesh.triangles.size()) +
                                    " triangles into more than " + std::to_string(max_triangles) +
                                    " (take a larger --alpha)",
                                kExitUsage);
                }
                continue;
            }
            const glm::vec3 p = corners[edge];
            const glm::vec3 q = corners[(edge + 1) % 3];
            const glm::vec3 r = corners[(edge + 2) % 3];
            const glm::vec3 m = 0.5f * (p + q);
            // (p, m, r) and (m, q, r) keep the winding of (p, q, r); the second is taken first.
            stack.push_back({p, m, r});
            stack.push_back({m, q, r});
        }
    }
    return out;
}

}  // namespace rc
