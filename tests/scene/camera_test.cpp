// The pinhole camera's image plane: the centre ray looks at look_at, the image edges lie at half
// the field of view on the chosen axis, x grows to the camera's right and y downwards.
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace rc {
namespace {

glm::vec3 direction_at(const shared::CameraParams& p, float x, float y) {
    const glm::vec3 top_left(p.top_left.x, p.top_left.y, p.top_left.z);
    const glm::vec3 right(p.right.x, p.right.y, p.right.z);
    const glm::vec3 down(p.down.x, p.down.y, p.down.z);
    return glm::normalize(top_left + right * (x / p.resolution.x) + down * (y / p.resolution.y));
}

float angle_degrees(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(
        std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

TEST(Camera, CentreAndEdgesFollowTheFieldOfView) {
    Camera camera;
    camera.position = {1.0f, 2.0f, 3.0f};
    camera.look_at = {1.0f, 2.0f, 10.0f};
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.fov_degrees = 60.0f;
    camera.fov_axis = FovAxis::kX;
    const shared::CameraParams p = camera_params(camera, 200, 100);
    const glm::vec3 forward(0.0f, 0.0f, 1.0f);
    EXPECT_NEAR(angle_degrees(direction_at(p, 100.0f, 50.0f), forward), 0.0f, 1e-3f);
    EXPECT_NEAR(angle_degrees(direction_at(p, 0.0f, 50.0f), forward), 30.0f, 1e-3f);
    EXPECT_NEAR(angle_degrees(direction_at(p, 200.0f, 50.0f), forward), 30.0f, 1e-3f);
    // Vertical half-angle from the aspect ratio: atan(tan(30) / 2).
    const float vertical = glm::degrees(std::atan(std::tan(glm::radians(30.0f)) * 0.5f));
    EXPECT_NEAR(angle_degrees(direction_at(p, 100.0f, 0.0f), forward), vertical, 1e-3f);
    // Image x grows along cross(forward, up) and y downwards.
    EXPECT_LT(direction_at(p, 200.0f, 50.0f).x, 0.0f);
    EXPECT_GT(direction_at(p, 100.0f, 0.0f).y, 0.0f);
    EXPECT_EQ(p.origin.x, 1.0f);
}

TEST(Camera, FovAxisChoosesTheExtent) {
    Camera camera;
    camera.position = {0.0f, 0.0f, 0.0f};
    camera.look_at = {0.0f, 0.0f, -1.0f};
    camera.fov_degrees = 40.0f;
    const glm::vec3 forward(0.0f, 0.0f, -1.0f);
    camera.fov_axis = FovAxis::kY;
    shared::CameraParams p = camera_params(camera, 300, 100);
    EXPECT_NEAR(angle_degrees(direction_at(p, 150.0f, 0.0f), forward), 20.0f, 1e-3f);
    camera.fov_axis = FovAxis::kSmaller;
    p = camera_params(camera, 300, 100);
    EXPECT_NEAR(angle_degrees(direction_at(p, 150.0f, 0.0f), forward), 20.0f, 1e-3f);
    camera.fov_axis = FovAxis::kLarger;
    p = camera_params(camera, 300, 100);
    EXPECT_NEAR(angle_degrees(direction_at(p, 0.0f, 50.0f), forward), 20.0f, 1e-3f);
    camera.fov_axis = FovAxis::kDiagonal;
    p = camera_params(camera, 300, 100);
    EXPECT_NEAR(angle_degrees(direction_at(p, 0.0f, 0.0f), forward), 20.0f, 1e-3f);
}

}  // namespace
}  // namespace rc
