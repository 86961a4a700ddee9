#include "scene/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "util/scale_free.h"

namespace rc {

namespace {

// A pixel filter by name, with the radius it has when none is given.
struct PixelFilterEntry {
    const char* name;
    int type;  // RC_FILTER_*
    float default_radius;
};

// The first one, box, stands for a type not listed.
constexpr PixelFilterEntry kPixelFilters[] = {{"box", RC_FILTER_BOX, 0.5f},
                                              {"tent", RC_FILTER_TENT, 1.0f},
                                              {"gaussian", RC_FILTER_GAUSSIAN, 1.5f}};

// A pixel sampler by name.
struct PixelSamplerEntry {
    const char* name;
    int type;  // RC_SAMPLER_*
};

// The last one, sobol, stands for a type not listed.
constexpr PixelSamplerEntry kPixelSamplers[] = {{"independent", RC_SAMPLER_INDEPENDENT},
                                                {"sobol", RC_SAMPLER_SOBOL}};

// The type of the entry of `table` named `name`, or -1.
template <class Entry, size_t N>
int type_named(const Entry (&table)[N], const std::string& name) {
    for (const Entry& entry : table) {
        if (name == entry.name) {
            return entry.type;
        }
    }
    return -1;
}

// The entry of `table` of type `type`, or `fallback`.
template <class Entry, size_t N>
const Entry& entry_of_type(const Entry (&table)[N], int type, const Entry& fallback) {
    for (const Entry& entry : table) {
        if (entry.type == type) {
            return entry;
        }
    }
    return fallback;
}

}  // namespace

int pixel_filter_type(const std::string& name) { return type_named(kPixelFilters, name); }

std::string pixel_filter_name(int type) {
    return entry_of_type(kPixelFilters, type, kPixelFilters[0]).name;
}

int pixel_sampler_type(const std::string& name) { return type_named(kPixelSamplers, name); }

std::string pixel_sampler_name(int type) {
    return entry_of_type(kPixelSamplers, type, kPixelSamplers[1]).name;
}

float default_filter_radius(int type) {
    return entry_of_type(kPixelFilters, type, kPixelFilters[0]).default_radius;
}

shared::CameraParams camera_params(const Camera& camera, int width, int height) {
    const glm::vec3 forward = scale_free_normalize(camera.look_at - camera.position);
    const glm::vec3 right = scale_free_normalize(glm::cross(forward, camera.up));
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
