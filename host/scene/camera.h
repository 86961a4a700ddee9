// The scene camera (a pinhole) and its device form.
#pragma once

#include <glm/vec3.hpp>

#include "shared/types.h"

namespace rc {

// The largest image width or height (scene files and --width/--height).
inline constexpr int kMaxImageSide = 1 << 16;

// Which image extent `fov` spans, as in Mitsuba's fov_axis.
enum class FovAxis { kX, kY, kDiagonal, kSmaller, kLarger };

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 0.0f};
    glm::vec3 look_at{0.0f, 0.0f, 1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 45.0f;
    FovAxis fov_axis = FovAxis::kX;
    int width = 512;
    int height = 512;
};

// The device camera for an image of width x height pixels. Image x grows along
// cross(forward, up) and image y downwards along -up.
shared::CameraParams camera_params(const Camera& camera, int width, int height);

}  // namespace rc
