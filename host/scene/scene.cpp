#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

#include "scene/transform.h"
#include "util/error.h"
#include "util/glm_helpers.h"

namespace rc {

int default_material(Scene& scene) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].name == "default") {
            return static_cast<int>(i);
        }
    }
    Material material;
    material.name = "default";
    scene.materials.push_back(material);
    return static_cast<int>(scene.materials.size() - 1);
}

void Scene::add_shape(Shape shape) {
    dropped_degenerate += drop_degenerate_triangles(shape.mesh);
    if (shape.materials.empty()) {
        shape.materials.push_back(default_material(*this));
    }
    shapes.push_back(std::move(shape));
}

void Scene::set_frame(double new_frame) {
    frame = new_frame;
    mesh = TriangleMesh{};
    normals.clear();
    uvs.clear();
    shading.clear();
    triangle_shape.clear();
    lights = LightSet{};

    // Camera.
    const glm::mat4 camera_motion = animation.motion(TrackTarget::kCamera, "", frame);
    camera = base_camera;
    camera.position = transform_point(camera_motion, base_camera.position);
    camera.look_at = transform_point(camera_motion, base_camera.look_at);
    camera.up = transform_direction(camera_motion, base_camera.up);

    std::vector<float> power;
    for (size_t s = 0; s < shapes.size(); ++s) {
        Shape& shape = shapes[s];
        const glm::mat4 to_world =
            animation.motion(TrackTarget::kShape, shape.name, frame) * shape.transform;
        // A mirroring transform reverses the winding; undo that so the winding normal stays on
        // the side the object-space winding named (and flip_normals flips it on purpose).
        const bool mirrored = glm::determinant(glm::mat3(to_world)) < 0.0f;
        const bool flip = mirrored != shape.flip_normals;
        const auto base = static_cast<unsigned>(mesh.positions.size());
        const int normal_base = shape.mesh.normals.empty() ? -1 : static_cast<int>(normals.size());
        const int uv_base = shape.mesh.uvs.empty() ? -1 : static_cast<int>(uvs.size());
        for (const glm::vec3& p : shape.mesh.positions) {
            mesh.positions.push_back(transform_point(to_world, p));
        }
        for (const glm::vec3& n : shape.mesh.normals) {
            const glm::vec3 world = transform_normal(to_world, n);
            normals.push_back(shape.flip_normals ? -world : world);
        }
        uvs.insert(uvs.end(), shape.mesh.uvs.begin(), shape.mesh.uvs.end());

        // Area lights: one per emitting material slot that has triangles.
        auto slot_of = [&](size_t t) {
            const int slot = shape.mesh.materials.empty() ? 0 : shape.mesh.materials[t];
            return slot >= 0 && static_cast<size_t>(slot) < shape.materials.size()
                       ? static_cast<size_t>(slot)
                       : size_t{0};
        };
        std::vector<size_t> slot_triangles(shape.materials.size(), 0);
        for (size_t t = 0; t < shape.mesh.triangles.size(); ++t) {
            ++slot_triangles[slot_of(t)];
        }
        std::vector<int> light_of_slot(shape.materials.size(), -1);
        for (size_t slot = 0; slot < shape.emission.size() && slot < shape.materials.size();
             ++slot) {
            const glm::vec3 radiance = shape.emission[slot];
            if (radiance == glm::vec3(0.0f) || slot_triangles[slot] == 0) {
                continue;
            }
            shared::Light light{};
            light.radiance = float4_of(radiance);
            light.info = {RC_LIGHT_AREA, 0, 0, 0};
            light_of_slot[slot] = static_cast<int>(lights.lights.size());
            lights.lights.push_back(light);
            power.push_back(0.0f);
        }
        std::vector<std::vector<unsigned>> light_triangles(shape.materials.size());
        std::vector<std::vector<float>> light_areas(shape.materials.size());

        shape.first_triangle = mesh.triangles.size();
        shape.triangle_count = shape.mesh.triangles.size();
        for (size_t t = 0; t < shape.mesh.triangles.size(); ++t) {
            glm::uvec3 local = shape.mesh.triangles[t];
            if (flip) {
                std::swap(local.y, local.z);
            }
            const auto primitive = static_cast<unsigned>(mesh.triangles.size());
            mesh.triangles.push_back(local + glm::uvec3(base));
            const size_t slot = slot_of(t);
            shared::TriangleShading sh{};
            sh.normals = {-1, -1, -1, shape.materials[slot]};
            sh.uvs = {-1, -1, -1, light_of_slot[slot]};
            if (normal_base >= 0) {
                sh.normals.x = normal_base + static_cast<int>(local.x);
                sh.normals.y = normal_base + static_cast<int>(local.y);
                sh.normals.z = normal_base + static_cast<int>(local.z);
            }
            if (uv_base >= 0) {
                sh.uvs.x = uv_base + static_cast<int>(local.x);
                sh.uvs.y = uv_base + static_cast<int>(local.y);
                sh.uvs.z = uv_base + static_cast<int>(local.z);
            }
            shading.push_back(sh);
            triangle_shape.push_back(static_cast<unsigned>(s));
            if (light_of_slot[slot] >= 0) {
                const glm::uvec3& w = mesh.triangles.back();
                const float area =
                    0.5f * glm::length(glm::cross(mesh.positions[w.y] - mesh.positions[w.x],
                                                  mesh.positions[w.z] - mesh.positions[w.x]));
                light_triangles[slot].push_back(primitive);
                light_areas[slot].push_back(area);
            }
        }
        for (size_t slot = 0; slot < shape.materials.size(); ++slot) {
            const int l = light_of_slot[slot];
            if (l < 0) {
                continue;
            }
            double total = 0.0;
            for (float a : light_areas[slot]) {
                total += a;
            }
            if (!(total > 0.0)) {
                throw Error("shape '" + shape.name + "': emitter has zero area");
            }
            shared::Light& light = lights.lights[l];
            light.info.y = static_cast<int>(lights.triangles.size());
            light.info.z = static_cast<int>(light_triangles[slot].size());
            light.shape = {static_cast<float>(total), 0.0f, 0.0f, 0.0f};
            double running = 0.0;
            for (size_t i = 0; i < light_triangles[slot].size(); ++i) {
                running += light_areas[slot][i];
                lights.triangles.push_back(light_triangles[slot][i]);
                lights.triangle_cdf.push_back(i + 1 == light_triangles[slot].size()
                                                  ? 1.0f
                                                  : static_cast<float>(running / total));
            }
            power[l] = 3.14159265f * static_cast<float>(total) *
                       luminance(glm::vec3(light.radiance.x, light.radiance.y, light.radiance.z));
        }
    }

    // Point, spot and environment emitters.
    glm::vec3 lower(std::numeric_limits<float>::max());
    glm::vec3 upper(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    const float scene_radius =
        mesh.positions.empty() ? 1.0f : std::max(0.5f * glm::length(upper - lower), 1e-6f);
    for (const Emitter& emitter : emitters) {
        const glm::mat4 motion = animation.motion(TrackTarget::kEmitter, emitter.name, frame);
        shared::Light light{};
        float light_power = 0.0f;
        if (emitter.kind == EmitterKind::kConstant) {
            light.info = {RC_LIGHT_CONSTANT, 0, 0, 0};
            light.radiance = float4_of(emitter.radiance);
            light_power = 3.14159265f * 3.14159265f * scene_radius * scene_radius *
                          luminance(emitter.radiance);
            lights.environment = static_cast<int>(lights.lights.size());
        } else {
            const glm::vec3 position = transform_point(motion, emitter.position);
            light.position = float4_of(position, 1.0f);
            if (emitter.kind == EmitterKind::kPoint) {
                light.info = {RC_LIGHT_POINT, 0, 0, 0};
                light.radiance = float4_of(emitter.intensity);
                light_power = 4.0f * 3.14159265f * luminance(emitter.intensity);
            } else {
                const glm::vec3 axis =
                    glm::normalize(transform_point(motion, emitter.look_at) - position);
                const float cutoff = glm::radians(emitter.cutoff_angle);
                const float beam = glm::radians(emitter.beam_width);
                light.info = {RC_LIGHT_SPOT, 0, 0, 0};
                light.axis = float4_of(axis, std::cos(cutoff));
                light.radiance = float4_of(emitter.intensity, std::cos(beam));
                light.shape = {0.0f, cutoff, beam, 0.0f};
                light_power = 2.0f * 3.14159265f * (1.0f - std::cos(0.5f * (cutoff + beam))) *
                              luminance(emitter.intensity);
            }
        }
        lights.lights.push_back(light);
        power.push_back(light_power);
    }

    // Selection by power (uniform when every light is black).
    double total_power = 0.0;
    for (float p : power) {
        total_power += p;
    }
    double running = 0.0;
    for (size_t l = 0; l < power.size(); ++l) {
        running += total_power > 0.0 ? power[l] : 1.0;
        const double total = total_power > 0.0 ? total_power : static_cast<double>(power.size());
        lights.cdf.push_back(l + 1 == power.size() ? 1.0f : static_cast<float>(running / total));
    }
}

}  // namespace rc
