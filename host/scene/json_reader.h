// Typed reads from a scene's JSON with errors that name the file and the key path
// ("scenes/x/scene.json: camera.fov: expected a number, got \"wide\"").
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/json_parse.h"

namespace rc {

class JsonReader {
   public:
    JsonReader(const nlohmann::json& value, std::string file, std::string path = "");

    // Throws Error("<file>: <path>: <message>").
    [[noreturn]] void fail(const std::string& message) const;
    [[noreturn]] void fail(const std::string& key, const std::string& message) const;

    bool has(const std::string& key) const;
    // Rejects keys outside `known`, naming the first unknown one.
    void allow_only(std::initializer_list<const char*> known) const;

    // Required when no fallback is given.
    float number(const std::string& key, std::optional<float> fallback = std::nullopt) const;
    // An integer in [min, max] (a value outside is an error naming the range, never wrapped).
    int integer(const std::string& key, std::optional<int> fallback = std::nullopt,
                int min = std::numeric_limits<int>::min(),
                int max = std::numeric_limits<int>::max()) const;
    std::string string(const std::string& key,
                       std::optional<std::string> fallback = std::nullopt) const;
    glm::vec3 vec3(const std::string& key, std::optional<glm::vec3> fallback = std::nullopt) const;
    // Two integers, each in [min, max].
    glm::ivec2 ivec2(const std::string& key, std::optional<glm::ivec2> fallback, int min,
                     int max) const;
    JsonReader object(const std::string& key) const;
    std::vector<JsonReader> array(const std::string& key) const;

    const nlohmann::json& value() const { return *value_; }
    const std::string& path() const { return path_; }

   private:
    const nlohmann::json& child(const std::string& key) const;
    std::string child_path(const std::string& key) const;

    const nlohmann::json* value_;
    std::string file_;
    std::string path_;
};

}  // namespace rc
