#include "scene/generated_meshes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <utility>

#include "shared/rng.h"

namespace rc {

TriangleMesh make_icosphere(glm::vec3 center, float radius, int subdivisions, float bump,
                            float bump_frequency) {
    const float t = (1.0f + std::sqrt(5.0f)) * 0.5f;
    std::vector<glm::vec3> unit = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                   {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                   {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (glm::vec3& v : unit) {
        v = glm::normalize(v);
    }
    std::vector<glm::uvec3> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<unsigned, unsigned>, unsigned> midpoints;
        auto midpoint = [&](unsigned a, unsigned b) {
            const auto key = std::minmax(a, b);
            const auto found = midpoints.find(key);
            if (found != midpoints.end()) {
                return found->second;
            }
            unit.push_back(glm::normalize(unit[a] + unit[b]));
            const auto index = static_cast<unsigned>(unit.size() - 1);
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<glm::uvec3> finer;
        finer.reserve(faces.size() * 4);
        for (const glm::uvec3& f : faces) {
            const unsigned ab = midpoint(f.x, f.y);
            const unsigned bc = midpoint(f.y, f.z);
            const unsigned ca = midpoint(f.z, f.x);
            finer.push_back({f.x, ab, ca});
            finer.push_back({f.y, bc, ab});
            finer.push_back({f.z, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    TriangleMesh mesh;
    mesh.positions.reserve(unit.size());
    for (const glm::vec3& n : unit) {
        float r = radius;
        if (bump > 0.0f) {
            r *= 1.0f + bump * std::sin(bump_frequency * n.x) * std::sin(bump_frequency * n.y) *
                            std::sin(bump_frequency * n.z);
        }
        mesh.positions.push_back(center + r * n);
    }
    mesh.triangles = std::move(faces);
    return mesh;
}

TriangleMesh make_triangle_soup(size_t count, uint32_t seed, glm::vec3 lower, glm::vec3 upper,
                                float max_edge) {
    TriangleMesh mesh;
    mesh.positions.reserve(count * 3);
    mesh.triangles.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        shared::RngStream rng = shared::rc_rng_stream(seed, 0x50u, static_cast<unsigned>(i), 0);
        glm::vec3 centre;
        for (int k = 0; k < 3; ++k) {
            centre[k] = lower[k] + (upper[k] - lower[k]) * shared::rc_rng_next_float(&rng);
        }
        const auto base = static_cast<unsigned>(mesh.positions.size());
        for (int v = 0; v < 3; ++v) {
            glm::vec3 offset;
            for (int k = 0; k < 3; ++k) {
                offset[k] = (shared::rc_rng_next_float(&rng) - 0.5f) * max_edge;
            }
            mesh.positions.push_back(centre + offset);
        }
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    return mesh;
}

TriangleMesh make_quad(glm::vec3 corner, glm::vec3 edge1, glm::vec3 edge2) {
    TriangleMesh mesh;
    mesh.positions = {corner, corner + edge1, corner + edge1 + edge2, corner + edge2};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return mesh;
}

TriangleMesh make_rectangle() {
    TriangleMesh mesh;
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return mesh;
}

TriangleMesh make_cube() {
    TriangleMesh mesh;
    // Each face: its outward axis and two in-plane axes with cross(u, v) = outward.
    const glm::vec3 axes[6][3] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
    };
    for (const auto& [out, u, v] : axes) {
        const auto base = static_cast<unsigned>(mesh.positions.size());
        mesh.positions.push_back(out - u - v);
        mesh.positions.push_back(out + u - v);
        mesh.positions.push_back(out + u + v);
        mesh.positions.push_back(out - u + v);
        mesh.uvs.insert(mesh.uvs.end(), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
        mesh.triangles.push_back({base, base + 1, base + 2});
        mesh.triangles.push_back({base, base + 2, base + 3});
    }
    return mesh;
}

TriangleMesh make_uv_sphere(glm::vec3 centre, float radius, int rings, int segments) {
    TriangleMesh mesh;
    const float pi = 3.14159265358979f;
    for (int i = 0; i <= rings; ++i) {
        const float theta = pi * static_cast<float>(i) / static_cast<float>(rings);
        // Exact poles, so that every triangle of a pole fan shares the same point.
        const float z = i == 0 ? -1.0f : (i == rings ? 1.0f : -std::cos(theta));
        const float r = (i == 0 || i == rings) ? 0.0f : std::sin(theta);
        for (int j = 0; j <= segments; ++j) {
            // The seam column repeats column 0 bit for bit.
            const int jj = j == segments ? 0 : j;
            const float phi = 2.0f * pi * static_cast<float>(jj) / static_cast<float>(segments);
            const glm::vec3 n(r * std::cos(phi), r * std::sin(phi), z);
            mesh.positions.push_back(centre + radius * n);
            mesh.normals.push_back(n);
            mesh.uvs.emplace_back(static_cast<float>(j) / static_cast<float>(segments),
                                  static_cast<float>(i) / static_cast<float>(rings));
        }
    }
    const int row = segments + 1;
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < segments; ++j) {
            const auto a = static_cast<unsigned>(i * row + j);
            const auto b = a + 1;
            const auto c = static_cast<unsigned>((i + 1) * row + j + 1);
            const auto d = c - 1;
            // Outward winding (counter-clockwise seen from outside); pole rows give zero-area
            // triangles, dropped by the scene.
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({a, c, d});
        }
    }
    return mesh;
}

Scene make_sphere_grid_scene(int side, int subdivisions) {
    Scene scene;
    scene.path = "generated:sphere-grid";
    const float spacing = 2.5f;
    const float extent = spacing * static_cast<float>(side);
    Shape ground;
    ground.name = "ground";
    ground.type = "generated";
    ground.mesh = make_quad({-extent, 0.0f, -extent}, {0.0f, 0.0f, 2.0f * extent},
                            {2.0f * extent, 0.0f, 0.0f});
    scene.add_shape(std::move(ground));
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            const glm::vec3 centre(spacing * (static_cast<float>(i) - 0.5f * (side - 1)), 1.0f,
                                   spacing * (static_cast<float>(j) - 0.5f * (side - 1)));
            Shape sphere;
            sphere.name = "sphere_" + std::to_string(i) + "_" + std::to_string(j);
            sphere.type = "generated";
            sphere.mesh = make_icosphere(centre, 1.0f, subdivisions, 0.08f, 9.0f);
            scene.add_shape(std::move(sphere));
        }
    }
    scene.base_camera.position = {0.0f, 0.6f * extent, -1.1f * extent};
    scene.base_camera.look_at = {0.0f, 0.5f, 0.0f};
    scene.base_camera.up = {0.0f, 1.0f, 0.0f};
    scene.base_camera.fov_degrees = 50.0f;
    scene.base_camera.width = 1024;
    scene.base_camera.height = 768;
    Emitter sky;
    sky.name = "sky";
    sky.kind = EmitterKind::kConstant;
    sky.radiance = glm::vec3(1.0f);
    scene.emitters.push_back(sky);
    scene.set_frame(0.0);
    return scene;
}

}  // namespace rc
