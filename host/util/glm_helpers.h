// Small helpers between GLM's vectors and the shared structs (kernels/shared/), and the luminance
// of a linear RGB colour. Include from .cpp files.
#pragma once

#include <glm/vec3.hpp>

#include "shared/compat.h"

namespace rc {

// (v, w) as a shared float4.
inline shared::float4 float4_of(glm::vec3 v, float w = 0.0f) { return {v.x, v.y, v.z, w}; }

// The xyz of a shared float4.
inline glm::vec3 vec3_of(const shared::float4& v) { return {v.x, v.y, v.z}; }

// Luminance of linear sRGB (Rec. 709 weights), the kernels' rc_luminance.
inline float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace rc
