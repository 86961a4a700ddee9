#include "scene/json_reader.h"

#include <algorithm>
#include <cmath>

#include "scene/scene_files.h"
#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

constexpr size_t kMaxStringBytes = kMaxSceneStringBytes;

std::string describe(const nlohmann::json& value) { return describe_json(value); }

// The integer `value` holds when it lies in [min, max].
std::optional<long long> integer_in(const nlohmann::json& value, long long min, long long max) {
    if (value.is_number_unsigned()) {
        const auto v = value.get<uint64_t>();
        if (v > static_cast<uint64_t>(std::numeric_limits<long long>::max())) {
            return std::nullopt;
        }
        const auto signed_value = static_cast<long long>(v);
        return signed_value >= min && signed_value <= max ? std::optional<long long>(signed_value)
                                                          : std::nullopt;
    }
    const auto v = value.get<int64_t>();
    return v >= min && v <= max ? std::optional<long long>(v) : std::nullopt;
}

std::string range_text(int min, int max) {
    return "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
}

}  // namespace

JsonReader::JsonReader(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {
    if (!value_->is_object()) {
        fail("expected an object, got " + describe(*value_));
    }
}

void JsonReader::fail(const std::string& message) const {
    throw Error(file_ + ": " + (path_.empty() ? std::string("top level") : path_) + ": " + message);
}

void JsonReader::fail(const std::string& key, const std::string& message) const {
    throw Error(file_ + ": " + child_path(key) + ": " + message);
}

std::string JsonReader::child_path(const std::string& key) const {
    return path_.empty() ? excerpt(key) : path_ + "." + excerpt(key);
}

bool JsonReader::has(const std::string& key) const { return value_->contains(key); }

const nlohmann::json& JsonReader::child(const std::string& key) const {
    if (!has(key)) {
        fail(key, "missing required key");
    }
    return value_->at(key);
}

void JsonReader::allow_only(std::initializer_list<const char*> known) const {
    for (const auto& item : value_->items()) {
        if (std::none_of(known.begin(), known.end(),
                         [&](const char* k) { return item.key() == k; })) {
            std::string list;
            for (const char* k : known) {
                list += list.empty() ? k : std::string(", ") + k;
            }
            fail(item.key(), "unknown key (known keys: " + list + ")");
        }
    }
}

float JsonReader::number(const std::string& key, std::optional<float> fallback) const {
    if (!has(key) && fallback) {
        return *fallback;
    }
    const nlohmann::json& value = child(key);
    if (!value.is_number()) {
        fail(key, "expected a number, got " + describe(value));
    }
    const double number = value.get<double>();
    if (!std::isfinite(static_cast<float>(number))) {
        fail(key, "number " + describe(value) + " is not finite in single precision");
    }
    return static_cast<float>(number);
}

int JsonReader::integer(const std::string& key, std::optional<int> fallback, int min,
                        int max) const {
    if (!has(key) && fallback) {
        return *fallback;
    }
    const nlohmann::json& value = child(key);
    if (!value.is_number_integer()) {
        fail(key, "expected an integer, got " + describe(value));
    }
    const std::optional<long long> result = integer_in(value, min, max);
    if (!result) {
        fail(key, "expected an integer in " + range_text(min, max) + ", got " + describe(value));
    }
    return static_cast<int>(*result);
}

std::string JsonReader::string(const std::string& key, std::optional<std::string> fallback) const {
    if (!has(key) && fallback) {
        return *fallback;
    }
    const nlohmann::json& value = child(key);
    if (!value.is_string()) {
        fail(key, "expected a string, got " + describe(value));
    }
    const std::string& text = value.get_ref<const std::string&>();
    if (text.size() > kMaxStringBytes) {
        fail(key, "a string of " + std::to_string(text.size()) + " bytes, more than the limit of " +
                      std::to_string(kMaxStringBytes) + ": " + describe(value));
    }
    return text;
}

glm::vec3 JsonReader::vec3(const std::string& key, std::optional<glm::vec3> fallback) const {
    if (!has(key) && fallback) {
        return *fallback;
    }
    const nlohmann::json& value = child(key);
    if (!value.is_array() || value.size() != 3 ||
        !std::all_of(value.begin(), value.end(), [](const auto& v) { return v.is_number(); })) {
        fail(key, "expected an array of three numbers, got " + describe(value));
    }
    glm::vec3 result;
    for (int i = 0; i < 3; ++i) {
        result[i] = static_cast<float>(value[i].get<double>());
        if (!std::isfinite(result[i])) {
            fail(key, "component " + std::to_string(i) + " is not finite");
        }
    }
    return result;
}

glm::ivec2 JsonReader::ivec2(const std::string& key, std::optional<glm::ivec2> fallback, int min,
                             int max) const {
    if (!has(key) && fallback) {
        return *fallback;
    }
    const nlohmann::json& value = child(key);
    if (!value.is_array() || value.size() != 2 ||
        !std::all_of(value.begin(), value.end(),
                     [](const auto& v) { return v.is_number_integer(); })) {
        fail(key, "expected an array of two integers, got " + describe(value));
    }
    glm::ivec2 result;
    for (int i = 0; i < 2; ++i) {
        const std::optional<long long> v = integer_in(value[i], min, max);
        if (!v) {
            fail(key,
                 "expected two integers in " + range_text(min, max) + ", got " + describe(value));
        }
        result[i] = static_cast<int>(*v);
    }
    return result;
}

JsonReader JsonReader::object(const std::string& key) const {
    const nlohmann::json& value = child(key);
    if (!value.is_object()) {
        fail(key, "expected an object, got " + describe(value));
    }
    return JsonReader(value, file_, child_path(key));
}

std::vector<JsonReader> JsonReader::array(const std::string& key) const {
    const nlohmann::json& value = child(key);
    if (!value.is_array()) {
        fail(key, "expected an array, got " + describe(value));
    }
    std::vector<JsonReader> items;
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string item_path = child_path(key) + "[" + std::to_string(i) + "]";
        if (!value[i].is_object()) {
            throw Error(file_ + ": " + item_path + ": expected an object, got " +
                        describe(value[i]));
        }
        items.emplace_back(value[i], file_, item_path);
    }
    return items;
}

}  // namespace rc
