// Emitters that are not shapes: point and spot lights and the constant environment. (Area lights
// are shapes with an emitter; see Shape::emission.)
#pragma once

#include <glm/vec3.hpp>
#include <string>

namespace rc {

enum class EmitterKind { kPoint, kSpot, kConstant };

struct Emitter {
    std::string name;
    EmitterKind kind = EmitterKind::kPoint;
    glm::vec3 position{0.0f};             // point, spot
    glm::vec3 look_at{0.0f, 0.0f, 1.0f};  // spot: the axis points at it
    glm::vec3 intensity{0.0f};            // point, spot: W/sr per channel
    glm::vec3 radiance{0.0f};             // constant: W/(m^2 sr)
    float cutoff_angle = 20.0f;           // spot, degrees
    float beam_width = 15.0f;             // spot, degrees
};

}  // namespace rc
