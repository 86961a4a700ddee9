#include "scene/gltf_validate.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "scene/json_parse.h"
#include "util/error.h"

namespace rc {
namespace {

using Json = nlohmann::json;

constexpr int kFloatComponent = 5126;  // accessor componentType FLOAT

// Error "<name>: <path>: <why>".
[[noreturn]] void refuse(const std::string& name, const std::string& path, const std::string& why) {
    throw Error(name + ": " + path + ": " + why);
}

// The array `object[key]`, when present, must hold `length` numbers.
void check_length(const Json& object, const char* key, size_t length, const std::string& name,
                  const std::string& path) {
    if (!object.is_object() || !object.contains(key)) {
        return;
    }
    const Json& value = object[key];
    const bool numbers =
        value.is_array() &&
        std::all_of(value.begin(), value.end(), [](const Json& v) { return v.is_number(); });
    if (!numbers || value.size() != length) {
        refuse(name, path + "." + key,
               describe_json(value) + " is not " + std::to_string(length) + " numbers");
    }
}

// `object[key]`, when present, must not be negative.
void check_not_negative(const Json& object, const char* key, const std::string& name,
                        const std::string& path) {
    if (object.is_object() && object.contains(key) && object[key].is_number() &&
        object[key].get<double>() < 0.0) {
        refuse(name, path + "." + key, describe_json(object[key]) + " is negative");
    }
}

// Each element of document[key] (an array of objects), with its path ("nodes[3]").
template <class Check>
void each(const Json& document, const char* key, const Check& check) {
    if (!document.contains(key) || !document[key].is_array()) {
        return;
    }
    const Json& list = document[key];
    for (size_t i = 0; i < list.size(); ++i) {
        check(list[i], std::string(key) + "[" + std::to_string(i) + "]");
    }
}

bool uses_extension(const Json& document, const std::string& extension) {
    if (!document.contains("extensionsUsed") || !document["extensionsUsed"].is_array()) {
        return false;
    }
    const Json& used = document["extensionsUsed"];
    return std::find(used.begin(), used.end(), Json(extension)) != used.end();
}

void check_nodes(const Json& document, const std::string& name) {
    each(document, "nodes", [&](const Json& node, const std::string& path) {
        check_length(node, "translation", 3, name, path);
        check_length(node, "rotation", 4, name, path);
        check_length(node, "scale", 3, name, path);
        check_length(node, "matrix", 16, name, path);
        if (node.is_object() && node.contains("matrix") &&
            (node.contains("translation") || node.contains("rotation") || node.contains("scale"))) {
            refuse(name, path,
                   "has both a matrix and a translation, rotation or scale (glTF 2.0 allows one)");
        }
    });
}

void check_materials_and_lights(const Json& document, const std::string& name) {
    each(document, "materials", [&](const Json& material, const std::string& path) {
        if (material.is_object() && material.contains("pbrMetallicRoughness")) {
            check_length(material["pbrMetallicRoughness"], "baseColorFactor", 4, name,
                         path + ".pbrMetallicRoughness");
        }
        check_length(material, "emissiveFactor", 3, name, path);
    });
    if (document.contains("extensions") && document["extensions"].is_object() &&
        document["extensions"].contains("KHR_lights_punctual")) {
        each(document["extensions"]["KHR_lights_punctual"], "lights",
             [&](const Json& light, const std::string& path) {
                 check_length(light, "color", 3, name, "extensions.KHR_lights_punctual." + path);
             });
    }
}

void check_buffers(const Json& document, const std::string& name) {
    each(document, "bufferViews", [&](const Json& view, const std::string& path) {
        for (const char* key : {"byteOffset", "byteLength", "byteStride"}) {
            check_not_negative(view, key, name, path);
        }
    });
    each(document, "accessors", [&](const Json& accessor, const std::string& path) {
        for (const char* key : {"byteOffset", "count"}) {
            check_not_negative(accessor, key, name, path);
        }
    });
}

// POSITION must be float unless KHR_mesh_quantization allows integers (glTF 2.0 §3.7.2.1).
void check_positions(const Json& document, const std::string& name) {
    if (uses_extension(document, "KHR_mesh_quantization") || !document.contains("accessors") ||
        !document["accessors"].is_array()) {
        return;
    }
    const Json& accessors = document["accessors"];
    each(document, "meshes", [&](const Json& mesh, const std::string& mesh_path) {
        each(mesh, "primitives", [&](const Json& primitive, const std::string& path) {
            if (!primitive.is_object() || !primitive.contains("attributes") ||
                !primitive["attributes"].is_object() ||
                !primitive["attributes"].contains("POSITION") ||
                !primitive["attributes"]["POSITION"].is_number_unsigned()) {
                return;
            }
            const size_t index = primitive["attributes"]["POSITION"].get<size_t>();
            if (index >= accessors.size() || !accessors[index].is_object() ||
                !accessors[index].contains("componentType")) {
                return;  // tinygltf names a missing accessor
            }
            const Json& type = accessors[index]["componentType"];
            if (type != Json(kFloatComponent)) {
                refuse(name, mesh_path + "." + path + ".attributes.POSITION",
                       "accessor " + std::to_string(index) + " has componentType " +
                           describe_json(type) +
                           ", not float (5126), without KHR_mesh_quantization in extensionsUsed");
            }
        });
    });
}

}  // namespace

void validate_gltf_json(const std::string& json_text, const std::string& name) {
    const Json document = parse_json(json_text, name);
    if (!document.is_object()) {
        refuse(name, "the document", "is not a JSON object");
    }
    check_nodes(document, name);
    check_materials_and_lights(document, name);
    check_buffers(document, name);
    check_positions(document, name);
}

}  // namespace rc
