#include "scene/transform.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "scene/json_reader.h"
#include "util/scale_free.h"

namespace rc {

glm::mat4 parse_transform(const JsonReader& reader, const std::string& key) {
    glm::mat4 result(1.0f);
    if (!reader.has(key)) {
        return result;
    }
    const nlohmann::json& list = reader.value().at(key);
    if (!list.is_array()) {
        reader.fail(key, "expected an array of transform steps");
    }
    std::vector<JsonReader> steps = reader.array(key);
    for (size_t i = 0; i < steps.size(); ++i) {
        const JsonReader& step = steps[i];
        if (step.value().size() != 1) {
            step.fail("a transform step has exactly one of translate, rotate, scale, matrix");
        }
        glm::mat4 m(1.0f);
        if (step.has("translate")) {
            m = glm::translate(glm::mat4(1.0f), step.vec3("translate"));
        } else if (step.has("rotate")) {
            const JsonReader rotate = step.object("rotate");
            rotate.allow_only({"axis", "angle"});
            const glm::vec3 axis = rotate.vec3("axis");
            if (glm::length(axis) == 0.0f) {
                rotate.fail("axis", "is the zero vector");
            }
            m = glm::rotate(glm::mat4(1.0f), glm::radians(rotate.number("angle")),
                            glm::normalize(axis));
        } else if (step.has("scale")) {
            const nlohmann::json& value = step.value().at("scale");
            const glm::vec3 s =
                value.is_number() ? glm::vec3(step.number("scale")) : step.vec3("scale");
            m = glm::scale(glm::mat4(1.0f), s);
        } else if (step.has("matrix")) {
            const nlohmann::json& value = step.value().at("matrix");
            if (!value.is_array() || value.size() != 16) {
                step.fail("matrix", "expected 16 numbers (row-major 4x4)");
            }
            for (int row = 0; row < 4; ++row) {
                for (int column = 0; column < 4; ++column) {
                    const nlohmann::json& entry = value[row * 4 + column];
                    if (!entry.is_number() || !std::isfinite(entry.get<float>())) {
                        step.fail("matrix", "entry " + std::to_string(row * 4 + column) +
                                                " is not a finite single-precision number");
                    }
                    m[column][row] = entry.get<float>();  // glm is column-major
                }
            }
        } else {
            step.fail("unknown transform step '" + step.value().begin().key() +
                      "' (translate, rotate, scale, matrix)");
        }
        result = m * result;
    }
    // The determinant in double: a uniform scale of 1e-17 has 1e-51, 0 in float, and is
    // invertible; one of 1e15 has 1e45, which overflows float though every entry is a float.
    const double determinant = linear_determinant(result);
    if (determinant == 0.0) {
        reader.fail(key, "is not invertible (determinant 0)");
    }
    return result;
}

glm::vec3 transform_point(const glm::mat4& m, glm::vec3 p) {
    const glm::vec4 q = m * glm::vec4(p, 1.0f);
    return glm::vec3(q) / q.w;
}

glm::vec3 transform_direction(const glm::mat4& m, glm::vec3 d) { return glm::mat3(m) * d; }

glm::vec3 transform_normal(const glm::mat4& m, glm::vec3 n) {
    const glm::vec3 world = glm::transpose(glm::inverse(glm::mat3(m))) * n;
    if (std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z)) {
        return scale_free_normalize(world);
    }
    // A scale whose determinant leaves float (1e-17: the inverse divides by 0): in double.
    const glm::dmat3 inverse = glm::inverse(glm::dmat3(glm::mat3(m)));
    return glm::vec3(glm::normalize(glm::transpose(inverse) * glm::dvec3(n)));
}

}  // namespace rc
