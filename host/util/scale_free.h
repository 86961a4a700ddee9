// Vector operations that hold at any scale single precision can store: a direction from a
// vector whose squared length leaves float's normal range (components below about 1e-19 or above
// about 1e19) is taken in double, and a vector is zero only when every component is. In range
// they compute what GLM computes in float, bit for bit.
#pragma once

#include <cfloat>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

namespace rc {

inline bool is_zero_vector(glm::vec3 v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }

// v / |v|: GLM's normalize where v's squared length is a normal float, else in double.
inline glm::vec3 scale_free_normalize(glm::vec3 v) {
    const float length2 = glm::dot(v, v);
    if (length2 >= FLT_MIN && length2 <= FLT_MAX) {
        return glm::normalize(v);
    }
    return glm::vec3(glm::normalize(glm::dvec3(v)));
}

// The determinant of a transform's linear part, in double: a uniform scale of 1e-17 (1e-51) or
// 1e15 (1e45) is not a float.
inline double linear_determinant(const glm::mat4& m) {
    return glm::determinant(glm::dmat3(glm::mat3(m)));
}

}  // namespace rc
