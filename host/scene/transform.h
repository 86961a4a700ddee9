// Transforms of shapes and emitters in scene files: a list of translate, rotate (axis-angle,
// degrees), scale and matrix (4x4, row-major) entries, applied in the listed order.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>

namespace rc {

class JsonReader;

// The transform under `key` of `reader` (identity when absent); Error naming the key path when
// an entry is malformed or the result is not invertible.
glm::mat4 parse_transform(const JsonReader& reader, const std::string& key);

glm::vec3 transform_point(const glm::mat4& m, glm::vec3 p);
glm::vec3 transform_direction(const glm::mat4& m, glm::vec3 d);
// Normals transform by the inverse transpose; the result is normalised.
glm::vec3 transform_normal(const glm::mat4& m, glm::vec3 n);

}  // namespace rc
