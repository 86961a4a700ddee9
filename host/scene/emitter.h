// Emitters that are not shapes: point, spot and distant lights and the constant environment.
// (Area lights are shapes with an emitter; see Shape::emission.)
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>

namespace rc {

enum class EmitterKind { kPoint, kSpot, kConstant, kDistant };

struct Emitter {
    std::string name;
    EmitterKind kind = EmitterKind::kPoint;
    glm::vec3 position{0.0f};                // point, spot
    glm::vec3 look_at{0.0f, 0.0f, 1.0f};     // spot: the axis points at it
    glm::vec3 intensity{0.0f};               // point, spot: W/sr per channel
    glm::vec3 radiance{0.0f};                // constant: W/(m^2 sr)
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // distant: the direction the light travels
    glm::vec3 irradiance{0.0f};              // distant: W/m^2 on a surface facing the light
    float cutoff_angle = 20.0f;              // spot, degrees
    float beam_width = 15.0f;                // spot, degrees
    // constant: a radiance map instead of `radiance` (scene/environment_map.h): its texture in
    // Scene::textures (the image times its scale), how it covers the sphere (RC_MAP_*), and the
    // map's frame (map-frame direction = map_from_world x world direction; a rotation, or a
    // rotation and a reflection).
    int map = -1;
    int map_mapping = 0;
    glm::mat3 map_from_world{1.0f};
    std::string map_file;  // the image the map was read from, for convert and messages
    glm::vec3 map_scale{1.0f};
};

}  // namespace rc
