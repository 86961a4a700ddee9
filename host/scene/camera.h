// The scene camera (a pinhole) and its device form.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "shared/types.h"

namespace rc {

// The largest image width or height (scene files and --width/--height).
inline constexpr int kMaxImageSide = 1 << 16;

// Which image extent `fov` spans, as in Mitsuba's fov_axis.
enum class FovAxis { kX, kY, kDiagonal, kSmaller, kLarger };

// The pixel reconstruction filter camera samples are drawn from (kernels/common/pixel_filter.h,
// docs/pixel-filters.md): box (the default, radius 0.5: uniform over the pixel), tent or Gaussian.
struct PixelFilter {
    int type = RC_FILTER_BOX;  // RC_FILTER_*
    float radius = 0.5f;       // pixels

    bool operator==(const PixelFilter&) const = default;
};

// "independent" or "sobol" as RC_SAMPLER_* (kernels/common/pixel_sampler.h); -1 for any other
// name.
int pixel_sampler_type(const std::string& name);
// RC_SAMPLER_* by name.
std::string pixel_sampler_name(int type);

// The range of filter radii (pixels) a scene or --filter-radius may give.
inline constexpr float kMinFilterRadius = 1e-3f;
inline constexpr float kMaxFilterRadius = 16.0f;

// "box", "tent" or "gaussian" as RC_FILTER_*; -1 for any other name.
int pixel_filter_type(const std::string& name);
// RC_FILTER_* by name.
std::string pixel_filter_name(int type);
// The radius a filter has when none is given: box 0.5, tent 1 (pbrt-v4's 1-pixel tent of the
// common references), Gaussian 1.5 (pbrt-v4's).
float default_filter_radius(int type);

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 0.0f};
    glm::vec3 look_at{0.0f, 0.0f, 1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 45.0f;
    FovAxis fov_axis = FovAxis::kX;
    int width = 512;
    int height = 512;
    PixelFilter filter;
    int sampler = RC_SAMPLER_SOBOL;  // RC_SAMPLER_*: where a pixel's camera samples fall
};

// The device camera (with its pixel filter) for an image of width x height pixels. Image x grows
// along cross(forward, up) and image y downwards along -up.
shared::CameraParams camera_params(const Camera& camera, int width, int height);

}  // namespace rc
