#include "scene/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace rc {

int pixel_filter_type(const std::string& name) {
    if (name == "box") {
        return RC_FILTER_BOX;
    }
    if (name == "tent") {
        return RC_FILTER_TENT;
    }
    if (name == "gaussian") {
        return RC_FILTER_GAUSSIAN;
    }
    return -1;
}

std::string pixel_filter_name(int type) {
    switch (type) {
        case RC_FILTER_TENT:
            return "tent";
        case RC_FILTER_GAUSSIAN:
            return "gaussian";
        default:
            return "box";
    }
}

int pixel_sampler_type(const std::string& name) {
    if (name == "independent") {
        return RC_SAMPLER_INDEPENDENT;
    }
    if (name == "sobol") {
        return RC_SAMPLER_SOBOL;
    }
    return -1;
}

std::string pixel_sampler_name(int type) {
    return type == RC_SAMPLER_INDEPENDENT ? "independent" : "sobol";
}

float default_filter_radius(int type) {
    switch (type) {
        case RC_FILTER_TENT:
            return 1.0f;
        case RC_FILTER_GAUSSIAN:
            return 1.5f;
        default:
            return 0.5f;
    }
}

shared::CameraParams camera_params(const Camera& camera, int width, int height) {
    const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float w = static_cast<float>(width);
    const float h = static_cast<float>(height);
    const float tangent = std::tan(glm::radians(camera.fov_degrees) * 0.5f);
    FovAxis axis = camera.fov_axis;
    if (axis == FovAxis::kSmaller) {
        axis = (w <= h) ? FovAxis::kX : FovAxis::kY;
    } else if (axis == FovAxis::kLarger) {
        axis = (w >= h) ? FovAxis::kX : FovAxis::kY;
    }
    float half_width = tangent;
    float half_height = tangent;
    switch (axis) {
        case FovAxis::kX:
            half_height = tangent * h / w;
            break;
        case FovAxis::kY:
            half_width = tangent * w / h;
            break;
        default: {
            const float diagonal = std::sqrt(w * w + h * h);
            half_width = tangent * w / diagonal;
            half_height = tangent * h / diagonal;
            break;
        }
    }
    const glm::vec3 top_left = forward - right * half_width + up * half_height;
    const glm::vec3 across = right * (2.0f * half_width);
    const glm::vec3 down = -up * (2.0f * half_height);
    shared::CameraParams params{};
    params.origin = {camera.position.x, camera.position.y, camera.position.z, 0.0f};
    params.top_left = {top_left.x, top_left.y, top_left.z, 0.0f};
    params.right = {across.x, across.y, across.z, 0.0f};
    params.down = {down.x, down.y, down.z, 0.0f};
    params.resolution = {width, height, 0, 0};
    params.filter = camera.filter.type;
    params.filter_radius = camera.filter.radius;
    params.sampler = camera.sampler;
    return params;
}

}  // namespace rc
