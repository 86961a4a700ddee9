// Scene::set_frame: the world data of one frame — the animated camera, every shape's triangles,
// shading and area lights in world space, the point, spot and environment emitters, and the
// light-selection distribution by power.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

#include "scene/environment_map.h"
#include "scene/mesh_bounds.h"
#include "scene/scene.h"
#include "scene/transform.h"
#include "util/error.h"
#include "util/glm_helpers.h"
#include "util/log.h"
#include "util/scale_free.h"
#include "util/text.h"

namespace rc {
namespace {

constexpr float kPi = 3.14159265f;

bool within_world(glm::vec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
           std::fabs(p.x) <= kMaxWorldCoordinate && std::fabs(p.y) <= kMaxWorldCoordinate &&
           std::fabs(p.z) <= kMaxWorldCoordinate;
}

std::string format_point(glm::vec3 p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
    return text;
}

std::string frame_text(double frame) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", frame);
    return text;
}

// What is wrong with the world coordinate `value` of `axis`: "x overflows float", "x = 2e+12".
std::string offending_coordinate(char axis, float value) {
    const std::string name(1, axis);
    if (std::isnan(value)) {
        return name + " is not a number (the transform adds infinities of opposite signs)";
    }
    if (std::isinf(value)) {
        return name + " overflows float";
    }
    char text[48];
    std::snprintf(text, sizeof text, " = %g", value);
    return name + text;
}

// Error unless every element of the object-to-world transform `m` is finite (translations or
// scales whose product overflows float), naming `what` and the first element that is not.
void check_transform(const glm::mat4& m, const std::string& what, double frame) {
    for (int row = 0; row < 4; ++row) {
        for (int column = 0; column < 4; ++column) {
            const float value = m[column][row];
            if (!std::isfinite(value)) {
                throw Error(what + ": its transform at frame " + frame_text(frame) +
                            " overflows float (row " + std::to_string(row + 1) + ", column " +
                            std::to_string(column + 1) + " is " +
                            (std::isnan(value) ? "not a number" : "infinite") +
                            "; check its translations, scales and animation)");
            }
        }
    }
}

// `object` (in object space) taken to world space by `to_world`, divided by w; Error unless it
// lies within the world range (Embree's build and the kernels' squared distances
// overflow beyond it), naming `what`, its object-space position and the offending value.
glm::vec3 world_point(const glm::mat4& to_world, glm::vec3 object, const std::string& what,
                      double frame) {
    const glm::vec4 h = to_world * glm::vec4(object, 1.0f);
    const std::string where =
        what + " at " + format_point(object) + " in object space, at frame " + frame_text(frame);
    if (h.w == 0.0f || !std::isfinite(h.w)) {
        char w[32];
        std::snprintf(w, sizeof w, "%g", h.w);
        throw Error(where + ": its transform gives w = " + w +
                    ", no point in world space (a matrix's bottom row must not take it to w = 0; "
                    "an affine one is 0 0 0 1)");
    }
    const glm::vec3 p = glm::vec3(h) / h.w;
    if (!within_world(p)) {
        const int axis = !within_world({p.x, 0, 0}) ? 0 : !within_world({0, p.y, 0}) ? 1 : 2;
        throw Error(where + ": world " + offending_coordinate("xyz"[axis], p[axis]) +
                    ", outside the world range of +-1e12 (check its size, transform and "
                    "animation)");
    }
    return p;
}

// The unit world direction of object direction `object` (a distant light's): the transform's
// linear part applied to it. Error when the transform collapses or overflows it.
glm::vec3 world_direction(const glm::mat4& to_world, glm::vec3 object, const std::string& what,
                          double frame) {
    const glm::vec3 d = glm::mat3(to_world) * object;
    const float length = glm::length(d);
    if (!(length > 0.0f) || !std::isfinite(length)) {
        throw Error(what + ": its transform takes its direction " + format_point(object) +
                    " to no direction at frame " + frame_text(frame) +
                    " (a transform must keep directions)");
    }
    return d / length;
}

// Error when world triangle `w` (triangle t of `what`) is smaller than single precision can
// intersect and shade: the device's products of edge components (the edges' cross product, its
// normal, the ray/triangle determinant) underflow float's normal range (2^-126, about 1.2e-38)
// when twice its area does: a scene scaled by about 1e-21 or less. Exactly 0 stays allowed (a
// triangle that collapses under rounding is never hit, as before).
void check_triangle_span(const TriangleMesh& mesh, const glm::uvec3& w, const std::string& what,
                         size_t t, double frame) {
    const glm::dvec3 a(mesh.positions[w.x]);
    const double span = glm::length(
        glm::cross(glm::dvec3(mesh.positions[w.y]) - a, glm::dvec3(mesh.positions[w.z]) - a));
    if (span > 0.0 && span < static_cast<double>(FLT_MIN)) {
        char text[160];
        std::snprintf(text, sizeof text,
                      ": triangle %zu at frame %s has twice its area %.3g in world space, below "
                      "single precision's normal range (%.3g)",
                      t, frame_text(frame).c_str(), span, static_cast<double>(FLT_MIN));
        throw Error(what + text +
                    ": the device cannot intersect or shade it (the scene is too small for float: "
                    "scale it up)");
    }
}

// The material slot of a shape's triangle t (slot 0 for a bad or missing index).
size_t material_slot(const Shape& shape, size_t t) {
    const int slot = shape.mesh.materials.empty() ? 0 : shape.mesh.materials[t];
    return slot >= 0 && static_cast<size_t>(slot) < shape.materials.size()
               ? static_cast<size_t>(slot)
               : size_t{0};
}

// The area lights of one shape: one per emitting material slot that has triangles, with the
// primitives and areas of their triangles.
struct ShapeLights {
    std::vector<int> light_of_slot;  // -1: the slot does not emit
    std::vector<std::vector<unsigned>> triangles;
    std::vector<std::vector<float>> areas;
};

// Adds a light (power to be set) for every emitting slot of `shape` with triangles.
ShapeLights open_area_lights(const Shape& shape, LightSet& lights, std::vector<float>& power) {
    std::vector<size_t> slot_triangles(shape.materials.size(), 0);
    for (size_t t = 0; t < shape.mesh.triangles.size(); ++t) {
        ++slot_triangles[material_slot(shape, t)];
    }
    ShapeLights result;
    result.light_of_slot.assign(shape.materials.size(), -1);
    result.triangles.resize(shape.materials.size());
    result.areas.resize(shape.materials.size());
    for (size_t slot = 0; slot < shape.emission.size() && slot < shape.materials.size(); ++slot) {
        const glm::vec3 radiance = shape.emission[slot];
        if (radiance == glm::vec3(0.0f) || slot_triangles[slot] == 0) {
            continue;
        }
        shared::Light light{};
        light.radiance = float4_of(radiance);
        light.kind = RC_LIGHT_AREA;
        result.light_of_slot[slot] = static_cast<int>(lights.lights.size());
        lights.lights.push_back(light);
        power.push_back(0.0f);
    }
    return result;
}

// Appends shape s's world triangles, vertices, normals, uvs and shading; records the triangles of
// its area lights.
void add_shape_triangles(Scene& scene, size_t s, ShapeLights& shape_lights) {
    Shape& shape = scene.shapes[s];
    TriangleMesh& mesh = scene.mesh;
    const glm::mat4 to_world =
        scene.animation.motion(TrackTarget::kShape, shape.name, scene.frame) * shape.transform;
    // A mirroring transform reverses the winding; undo that so the winding normal stays on
    // the side the object-space winding named (and flip_normals flips it on purpose).
    const bool mirrored = linear_determinant(to_world) < 0.0;
    const bool flip = mirrored != shape.flip_normals;
    const auto base = static_cast<unsigned>(mesh.positions.size());
    const int normal_base =
        shape.mesh.normals.empty() ? -1 : static_cast<int>(scene.normals.size());
    const int uv_base = shape.mesh.uvs.empty() ? -1 : static_cast<int>(scene.uvs.size());
    const std::string shape_name =
        "shape '" + excerpt(shape.name) + "' (index " + std::to_string(s) + ")";
    check_transform(to_world, shape_name, scene.frame);
    for (size_t v = 0; v < shape.mesh.positions.size(); ++v) {
        mesh.positions.push_back(world_point(to_world, shape.mesh.positions[v],
                                             shape_name + ": vertex " + std::to_string(v),
                                             scene.frame));
    }
    for (const glm::vec3& n : shape.mesh.normals) {
        const glm::vec3 world = transform_normal(to_world, n);
        if (!std::isfinite(world.x) || !std::isfinite(world.y) || !std::isfinite(world.z)) {
            throw Error(shape_name + ": a vertex normal is not finite in world space at frame " +
                        frame_text(scene.frame) + " (a near-singular transform)");
        }
        scene.normals.push_back(shape.flip_normals ? -world : world);
    }
    scene.uvs.insert(scene.uvs.end(), shape.mesh.uvs.begin(), shape.mesh.uvs.end());

    shape.first_triangle = mesh.triangles.size();
    shape.triangle_count = shape.mesh.triangles.size();
    for (size_t t = 0; t < shape.mesh.triangles.size(); ++t) {
        glm::uvec3 local = shape.mesh.triangles[t];
        if (flip) {
            std::swap(local.y, local.z);
        }
        const auto primitive = static_cast<unsigned>(mesh.triangles.size());
        mesh.triangles.push_back(local + glm::uvec3(base));
        check_triangle_span(mesh, mesh.triangles.back(), shape_name, t, scene.frame);
        const size_t slot = material_slot(shape, t);
        const int light = shape_lights.light_of_slot[slot];
        shared::TriangleShading sh{};
        sh.normal0 = sh.normal1 = sh.normal2 = -1;
        sh.material = shape.materials[slot];
        sh.uv0 = sh.uv1 = sh.uv2 = -1;
        sh.light = light;
        if (normal_base >= 0) {
            sh.normal0 = normal_base + static_cast<int>(local.x);
            sh.normal1 = normal_base + static_cast<int>(local.y);
            sh.normal2 = normal_base + static_cast<int>(local.z);
        }
        if (uv_base >= 0) {
            sh.uv0 = uv_base + static_cast<int>(local.x);
            sh.uv1 = uv_base + static_cast<int>(local.y);
            sh.uv2 = uv_base + static_cast<int>(local.z);
        }
        scene.shading.push_back(sh);
        scene.triangle_shape.push_back(static_cast<unsigned>(s));
        if (light >= 0) {
            const glm::uvec3& w = mesh.triangles.back();
            // In double: the squared length of the edges' cross product leaves float's range
            // for edges below about 1e-9.5 or above 4e9 (a scene scaled by 1e-15 or 1e8).
            const glm::dvec3 a(mesh.positions[w.x]);
            const float area = static_cast<float>(
                0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[w.y]) - a,
                                             glm::dvec3(mesh.positions[w.z]) - a)));
            shape_lights.triangles[slot].push_back(primitive);
            shape_lights.areas[slot].push_back(area);
        }
    }
}

// Completes the shape's area lights: total area, triangle distribution by area, power.
void close_area_lights(const Shape& shape, const ShapeLights& shape_lights, LightSet& lights,
                       std::vector<float>& power) {
    for (size_t slot = 0; slot < shape.materials.size(); ++slot) {
        const int l = shape_lights.light_of_slot[slot];
        if (l < 0) {
            continue;
        }
        const std::vector<float>& areas = shape_lights.areas[slot];
        const std::vector<unsigned>& triangles = shape_lights.triangles[slot];
        double total = 0.0;
        for (float a : areas) {
            total += a;
        }
        if (!(total > 0.0)) {
            throw Error("shape '" + shape.name + "': emitter has zero area");
        }
        shared::Light& light = lights.lights[l];
        light.first_triangle = static_cast<int>(lights.triangles.size());
        light.triangle_count = static_cast<int>(triangles.size());
        light.area = static_cast<float>(total);
        double running = 0.0;
        for (size_t i = 0; i < triangles.size(); ++i) {
            running += areas[i];
            lights.triangles.push_back(triangles[i]);
            lights.triangle_cdf.push_back(
                i + 1 == triangles.size() ? 1.0f : static_cast<float>(running / total));
        }
        power[l] = kPi * static_cast<float>(total) *
                   luminance(glm::vec3(light.radiance.x, light.radiance.y, light.radiance.z));
    }
}

// Error when the frame's triangles span less than kMinSceneExtent (but more than a point).
void check_scene_extent(const TriangleMesh& mesh, double frame) {
    check_least_extent(mesh, kMinSceneExtent, "", " at frame " + frame_text(frame),
                       "the least single precision can render, 2^-42",
                       "the device's ray/triangle test underflows float (scale the scene up)");
}

// Half the diagonal of the frame's bounding box (1 for an empty scene or a single point): no
// absolute floor, so that an environment's share of the light power is that of the scene at any
// scale.
float scene_radius(const TriangleMesh& mesh) {
    const float diagonal = mesh_diagonal(mesh);
    return diagonal > 0.0f ? 0.5f * diagonal : 1.0f;
}

// The device light of a point, spot, distant or environment emitter at the frame, and its power.
shared::Light emitter_light(const Emitter& emitter, const std::string& emitter_name,
                            const glm::mat4& motion, float radius, double frame, float* power) {
    shared::Light light{};
    if (emitter.kind == EmitterKind::kConstant) {
        light.kind = RC_LIGHT_CONSTANT;
        light.map = -1;  // a map is added by the caller (scene/environment_map.h)
        light.radiance = float4_of(emitter.radiance);
        *power = kPi * kPi * radius * radius * luminance(emitter.radiance);
        return light;
    }
    check_transform(motion, emitter_name, frame);
    if (emitter.kind == EmitterKind::kDistant) {
        // The light crossing the scene's bounding disk (pbrt-v4 §12.4: Phi = E pi r^2).
        light.kind = RC_LIGHT_DISTANT;
        light.axis = float4_of(world_direction(motion, emitter.direction, emitter_name, frame));
        light.radiance = float4_of(emitter.irradiance);
        *power = kPi * radius * radius * luminance(emitter.irradiance);
        return light;
    }
    const glm::vec3 position = world_point(motion, emitter.position, emitter_name, frame);
    light.position = float4_of(position);
    if (emitter.kind == EmitterKind::kPoint) {
        light.kind = RC_LIGHT_POINT;
        light.radiance = float4_of(emitter.intensity);
        *power = 4.0f * kPi * luminance(emitter.intensity);
        return light;
    }
    const glm::vec3 target =
        world_point(motion, emitter.look_at, emitter_name + ": look_at", frame);
    const glm::vec3 axis = glm::normalize(target - position);
    const float cutoff = glm::radians(emitter.cutoff_angle);
    const float beam = glm::radians(emitter.beam_width);
    light.kind = RC_LIGHT_SPOT;
    light.axis = float4_of(axis);
    light.radiance = float4_of(emitter.intensity);
    light.cutoff = cutoff;
    light.beam = beam;
    light.cos_cutoff = std::cos(cutoff);
    light.cos_beam = std::cos(beam);
    *power = 2.0f * kPi * (1.0f - std::cos(0.5f * (cutoff + beam))) * luminance(emitter.intensity);
    return light;
}

// Selection by power (uniform when every light is black).
std::vector<float> selection_cdf(const std::vector<float>& power) {
    double total_power = 0.0;
    for (float p : power) {
        total_power += p;
    }
    std::vector<float> cdf;
    double running = 0.0;
    for (size_t l = 0; l < power.size(); ++l) {
        running += total_power > 0.0 ? power[l] : 1.0;
        const double total = total_power > 0.0 ? total_power : static_cast<double>(power.size());
        cdf.push_back(l + 1 == power.size() ? 1.0f : static_cast<float>(running / total));
    }
    return cdf;
}

// A camera far outside the world range, or posed so that its view direction overflows, sees
// nothing: the "renders black with no word". Warned (an error under --strict).
void warn_unless_camera_view_finite(const Camera& camera, double frame) {
    const glm::vec3 forward = camera.look_at - camera.position;
    const glm::vec3 right = glm::cross(forward, camera.up);
    const bool finite = within_world(camera.position) && within_world(camera.look_at) &&
                        within_world(forward) && std::isfinite(glm::length(right)) &&
                        !is_zero_vector(right);
    if (!finite) {
        log_warning("camera at frame " + frame_text(frame) + ": position " +
                    format_point(camera.position) + " looking at " + format_point(camera.look_at) +
                    " overflows the view (outside the world range "
                    "or a degenerate up): the image will be black");
    }
}

}  // namespace

void Scene::set_frame(double new_frame) {
    frame = new_frame;
    mesh = TriangleMesh{};
    normals.clear();
    uvs.clear();
    shading.clear();
    triangle_shape.clear();
    lights = LightSet{};

    const glm::mat4 camera_motion = animation.motion(TrackTarget::kCamera, "", frame);
    camera = base_camera;
    camera.position = transform_point(camera_motion, base_camera.position);
    camera.look_at = transform_point(camera_motion, base_camera.look_at);
    camera.up = transform_direction(camera_motion, base_camera.up);
    warn_unless_camera_view_finite(camera, frame);

    std::vector<float> power;
    for (size_t s = 0; s < shapes.size(); ++s) {
        ShapeLights shape_lights = open_area_lights(shapes[s], lights, power);
        add_shape_triangles(*this, s, shape_lights);
        close_area_lights(shapes[s], shape_lights, lights, power);
    }
    check_scene_extent(mesh, frame);
    const float radius = scene_radius(mesh);
    for (size_t e = 0; e < emitters.size(); ++e) {
        const Emitter& emitter = emitters[e];
        const glm::mat4 motion = animation.motion(TrackTarget::kEmitter, emitter.name, frame);
        float light_power = 0.0f;
        if (emitter.kind == EmitterKind::kConstant) {
            lights.environment = static_cast<int>(lights.lights.size());
        }
        const std::string name =
            "emitter '" + excerpt(emitter.name) + "' (index " + std::to_string(e) + ")";
        shared::Light light = emitter_light(emitter, name, motion, radius, frame, &light_power);
        if (emitter.kind == EmitterKind::kConstant && emitter.map >= 0) {
            const glm::vec3 mean = add_environment_map(
                emitter, textures[static_cast<size_t>(emitter.map)], lights.triangle_cdf, light);
            light_power = kPi * kPi * radius * radius * luminance(mean);
        }
        lights.lights.push_back(light);
        power.push_back(light_power);
    }
    lights.cdf = selection_cdf(power);
}

}  // namespace rc
