#include "ray_sets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <map>

#include "shared/rng.h"

namespace rc::test {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

glm::vec3 uniform_direction(shared::RngStream& rng) {
    const float z = 1.0f - 2.0f * shared::rc_rng_next_float(&rng);
    const float phi = 6.2831853f * shared::rc_rng_next_float(&rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::vec3 point_in(const Bounds& bounds, float margin, shared::RngStream& rng) {
    const glm::vec3 grow = (bounds.upper - bounds.lower) * margin;
    glm::vec3 p;
    for (int k = 0; k < 3; ++k) {
        p[k] =
            bounds.lower[k] - grow[k] +
            (bounds.upper[k] - bounds.lower[k] + 2.0f * grow[k]) * shared::rc_rng_next_float(&rng);
    }
    return p;
}

unsigned pick(size_t count, shared::RngStream& rng) {
    return static_cast<unsigned>(shared::rc_rng_next_uint(&rng) % count);
}

}  // namespace

Bounds mesh_bounds(const TriangleMesh& mesh) {
    Bounds b{glm::vec3(kInf), glm::vec3(-kInf)};
    for (const glm::vec3& p : mesh.positions) {
        b.lower = glm::min(b.lower, p);
        b.upper = glm::max(b.upper, p);
    }
    return b;
}

shared::Ray make_ray(glm::vec3 origin, glm::vec3 direction, float tmin, float tmax) {
    shared::Ray ray;
    ray.origin = {origin.x, origin.y, origin.z, tmin};
    ray.direction = {direction.x, direction.y, direction.z, tmax};
    return ray;
}

std::vector<shared::Ray> random_rays(const Bounds& bounds, size_t count, uint32_t seed,
                                     float margin) {
    std::vector<shared::Ray> rays;
    rays.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        shared::RngStream rng = shared::rc_rng_stream(seed, 1, static_cast<unsigned>(i), 0);
        const glm::vec3 origin = point_in(bounds, margin, rng);
        rays.push_back(make_ray(origin, uniform_direction(rng), 0.0f, kInf));
    }
    return rays;
}

namespace {

using Position = std::array<float, 3>;

Position key(const glm::vec3& p) { return {p.x, p.y, p.z}; }

// Triangles around positions, matched by exact coordinates (meshes of separate shapes meet at
// equal positions, not shared indices).
class Adjacency {
   public:
    explicit Adjacency(const TriangleMesh& mesh) : mesh_(mesh) {
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            for (int k = 0; k < 3; ++k) {
                around_[key(mesh.positions[mesh.triangles[t][k]])].push_back(t);
            }
        }
    }

    std::vector<size_t> triangles_at(const glm::vec3& p) const {
        const auto found = around_.find(key(p));
        return found == around_.end() ? std::vector<size_t>{} : found->second;
    }

    bool has_vertex(size_t t, const glm::vec3& p) const {
        for (int k = 0; k < 3; ++k) {
            if (key(mesh_.positions[mesh_.triangles[t][k]]) == key(p)) {
                return true;
            }
        }
        return false;
    }

    glm::vec3 normal(size_t t) const {
        const glm::uvec3& i = mesh_.triangles[t];
        return glm::normalize(glm::cross(mesh_.positions[i.y] - mesh_.positions[i.x],
                                         mesh_.positions[i.z] - mesh_.positions[i.x]));
    }

    // Every triangle of `around` faces `direction` the same way, none at a grazing angle.
    bool transversal(const std::vector<size_t>& around, const glm::vec3& direction) const {
        const glm::vec3 d = glm::normalize(direction);
        int sign = 0;
        for (size_t t : around) {
            const float cosine = glm::dot(normal(t), d);
            if (std::fabs(cosine) < 0.05f) {
                return false;
            }
            const int s = cosine > 0.0f ? 1 : -1;
            if (sign != 0 && s != sign) {
                return false;
            }
            sign = s;
        }
        return sign != 0;
    }

    // The fan around vertex p is closed: every other vertex of the fan is shared by exactly two
    // of its triangles.
    bool closed_fan(const glm::vec3& p, const std::vector<size_t>& around) const {
        std::map<Position, int> uses;
        for (size_t t : around) {
            for (int k = 0; k < 3; ++k) {
                const Position q = key(mesh_.positions[mesh_.triangles[t][k]]);
                if (q != key(p)) {
                    ++uses[q];
                }
            }
        }
        return !uses.empty() &&
               std::all_of(uses.begin(), uses.end(), [](const auto& u) { return u.second == 2; });
    }

   private:
    const TriangleMesh& mesh_;
    std::map<Position, std::vector<size_t>> around_;
};

// Where a ray is aimed, and whether it crosses the surface there.
struct Aim {
    glm::vec3 target;
    bool crossing;
};

// `count` rays from random points of `bounds` (ray i drawing from stream (seed, `stream`, i)) to
// the targets `aim_at(rng, origin)` picks with the same stream.
template <class AimAt>
AimedRays aimed_rays(const Bounds& bounds, size_t count, uint32_t seed, unsigned stream,
                     const AimAt& aim_at) {
    AimedRays aimed;
    for (size_t i = 0; i < count; ++i) {
        shared::RngStream rng = shared::rc_rng_stream(seed, stream, static_cast<unsigned>(i), 0);
        const glm::vec3 origin = point_in(bounds, 0.2f, rng);
        const Aim aim = aim_at(rng, origin);
        aimed.rays.push_back(make_ray(origin, aim.target - origin, 0.0f, kInf));
        aimed.crossing.push_back(aim.crossing);
    }
    return aimed;
}

}  // namespace

AimedRays vertex_aimed_rays(const TriangleMesh& mesh, const Bounds& bounds, size_t count,
                            uint32_t seed) {
    const Adjacency adjacency(mesh);
    return aimed_rays(bounds, count, seed, 2, [&](shared::RngStream& rng, glm::vec3 origin) {
        const glm::vec3 target = mesh.positions[pick(mesh.positions.size(), rng)];
        const std::vector<size_t> around = adjacency.triangles_at(target);
        return Aim{target, adjacency.closed_fan(target, around) &&
                               adjacency.transversal(around, target - origin)};
    });
}

AimedRays edge_aimed_rays(const TriangleMesh& mesh, const Bounds& bounds, size_t count,
                          uint32_t seed) {
    const Adjacency adjacency(mesh);
    return aimed_rays(bounds, count, seed, 3, [&](shared::RngStream& rng, glm::vec3 origin) {
        const glm::uvec3& t = mesh.triangles[pick(mesh.triangles.size(), rng)];
        const unsigned edge = pick(3, rng);
        const glm::vec3 a = mesh.positions[t[edge]];
        const glm::vec3 b = mesh.positions[t[(edge + 1) % 3]];
        const float s = shared::rc_rng_next_float(&rng);
        const glm::vec3 target = a + s * (b - a);
        std::vector<size_t> sharing;
        for (size_t candidate : adjacency.triangles_at(a)) {
            if (adjacency.has_vertex(candidate, b)) {
                sharing.push_back(candidate);
            }
        }
        // An interior point of an edge shared by two triangles (the end points are vertices).
        const bool interior = s > 0.0f && s < 1.0f && target != a && target != b;
        return Aim{target, interior && sharing.size() == 2 &&
                               adjacency.transversal(sharing, target - origin)};
    });
}

std::vector<shared::Ray> surface_segments(const TriangleMesh& mesh,
                                          const std::vector<shared::Ray>& surface_rays,
                                          uint32_t seed) {
    std::vector<shared::Ray> rays;
    rays.reserve(surface_rays.size());
    for (size_t i = 0; i < surface_rays.size(); ++i) {
        shared::RngStream rng = shared::rc_rng_stream(seed, 4, static_cast<unsigned>(i), 0);
        const glm::uvec3& t = mesh.triangles[pick(mesh.triangles.size(), rng)];
        float u = shared::rc_rng_next_float(&rng);
        float v = shared::rc_rng_next_float(&rng);
        if (u + v > 1.0f) {
            u = 1.0f - u;
            v = 1.0f - v;
        }
        const glm::vec3 target = (1.0f - u - v) * mesh.positions[t.x] + u * mesh.positions[t.y] +
                                 v * mesh.positions[t.z];
        const glm::vec3 origin(surface_rays[i].origin.x, surface_rays[i].origin.y,
                               surface_rays[i].origin.z);
        rays.push_back(make_ray(origin, target - origin, 0.0f, 0.999f));
    }
    return rays;
}

std::vector<shared::Ray> malformed_rays() {
    const glm::vec3 o(0.1f, 0.2f, 0.3f);
    const glm::vec3 d(0.3f, -0.5f, 0.8f);
    return {
        make_ray({kNaN, o.y, o.z}, d, 0.0f, kInf),
        make_ray(o, {d.x, kNaN, d.z}, 0.0f, kInf),
        make_ray({kInf, o.y, o.z}, d, 0.0f, kInf),
        make_ray({o.x, -kInf, o.z}, d, 0.0f, kInf),
        make_ray(o, {kInf, d.y, d.z}, 0.0f, kInf),
        make_ray(o, {d.x, d.y, -kInf}, 0.0f, kInf),
        make_ray(o, {kInf, kInf, kInf}, 0.0f, kInf),
        make_ray(o, {kNaN, kNaN, kNaN}, 0.0f, kInf),
        make_ray(o, {0.0f, 0.0f, 0.0f}, 0.0f, kInf),
        make_ray(o, d, kNaN, kInf),
        make_ray(o, d, 0.0f, kNaN),
        make_ray(o, d, 2.0f, 1.0f),
        make_ray(o, d, -1.0f, kInf),
        make_ray(o, d, kInf, kInf),
    };
}

}  // namespace rc::test
