#include "scene/pbrt_params.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>

#include "scene/spectra.h"
#include "util/error.h"
#include "util/log.h"
#include "util/text.h"

namespace rc {

PbrtParams::PbrtParams(const PbrtDirective& directive, std::string what)
    : params_(directive.params), used_(directive.params.size(), false), what_(std::move(what)) {
    std::set<std::string> names;
    for (const PbrtParam& param : params_) {
        if (!names.insert(param.name).second) {
            fail("parameter \"" + excerpt(param.name) + "\" is given twice");
        }
    }
}

bool PbrtParams::has(const std::string& name) const {
    return std::any_of(params_.begin(), params_.end(),
                       [&](const PbrtParam& p) { return p.name == name; });
}

std::string PbrtParams::type_of(const std::string& name) const {
    for (const PbrtParam& p : params_) {
        if (p.name == name) {
            return p.type;
        }
    }
    return "";
}

void PbrtParams::fail(const std::string& message) const { throw Error(what_ + ": " + message); }

void PbrtParams::refuse(const std::string& message) const {
    throw Error(what_ + ": " + message, kExitUnsupported);
}

const PbrtParam* PbrtParams::find(const std::string& name, const std::vector<std::string>& types) {
    for (size_t i = 0; i < params_.size(); ++i) {
        if (params_[i].name != name) {
            continue;
        }
        used_[i] = true;
        if (std::find(types.begin(), types.end(), params_[i].type) == types.end()) {
            std::string list;
            for (const std::string& t : types) {
                list += (list.empty() ? "" : " or ") + t;
            }
            fail("parameter \"" + excerpt(name) + "\" must be of type " + list + ", not " +
                 excerpt(params_[i].type));
        }
        return &params_[i];
    }
    return nullptr;
}

namespace {

std::string declared(const PbrtParam& p) { return "\"" + excerpt(p.type + " " + p.name) + "\""; }

}  // namespace

const PbrtParam* PbrtParams::find_single(const std::string& name,
                                         const std::vector<std::string>& types, bool strings,
                                         const std::string& expects) {
    const PbrtParam* p = find(name, types);
    if (p != nullptr && (strings ? p->strings.size() : p->numbers.size()) != 1) {
        fail("parameter " + declared(*p) + " expects " + expects);
    }
    return p;
}

float PbrtParams::get_float(const std::string& name, float fallback) {
    const PbrtParam* p = find_single(name, {"float"}, false, "one number");
    if (p == nullptr) {
        return fallback;
    }
    const auto value = static_cast<float>(p->numbers[0]);
    if (!std::isfinite(value)) {
        fail("parameter " + declared(*p) + " overflows float");
    }
    return value;
}

int PbrtParams::get_int(const std::string& name, int fallback) {
    const PbrtParam* p = find_single(name, {"integer"}, false, "one integer");
    return p == nullptr ? fallback : static_cast<int>(p->numbers[0]);
}

bool PbrtParams::get_bool(const std::string& name, bool fallback) {
    const PbrtParam* p = find_single(name, {"bool"}, true, "one of true or false");
    return p == nullptr ? fallback : p->strings[0] == "true";
}

std::string PbrtParams::get_string(const std::string& name, const std::string& fallback) {
    const PbrtParam* p = find_single(name, {"string", "texture"}, true, "one string");
    return p == nullptr ? fallback : p->strings[0];
}

std::optional<glm::vec3> PbrtParams::get_point3(const std::string& name) {
    const std::vector<double> v = get_numbers(name, {"point3", "point", "vector3", "vector"}, 3);
    if (v.empty()) {
        return std::nullopt;
    }
    if (v.size() != 3) {
        fail("parameter \"" + excerpt(name) + "\" expects one point (3 numbers)");
    }
    return glm::vec3(v[0], v[1], v[2]);
}

std::vector<double> PbrtParams::get_numbers(const std::string& name,
                                            const std::vector<std::string>& types, size_t width) {
    const PbrtParam* p = find(name, types);
    if (p == nullptr) {
        return {};
    }
    if (p->numbers.size() % width != 0) {
        fail("parameter " + declared(*p) + " has " + std::to_string(p->numbers.size()) +
             " numbers, not a multiple of " + std::to_string(width));
    }
    for (double value : p->numbers) {
        if (!std::isfinite(static_cast<float>(value))) {
            fail("parameter " + declared(*p) + " has a value that overflows float");
        }
    }
    return p->numbers;
}

std::optional<glm::vec3> PbrtParams::get_rgb(const std::string& name) {
    const std::string type = type_of(name);
    if (type == "blackbody" || type == "spectrum") {
        find(name, {type});
        refuse("parameter \"" + excerpt(type + " " + name) + "\": " + type +
               " spectra are not supported (radcache renders in RGB: give \"rgb " + excerpt(name) +
               "\")");
    }
    const std::vector<double> v = get_numbers(name, {"rgb", "color"}, 3);
    if (v.empty()) {
        return std::nullopt;
    }
    if (v.size() != 3) {
        fail("parameter \"rgb " + excerpt(name) + "\" expects 3 numbers");
    }
    return glm::vec3(v[0], v[1], v[2]);
}

std::optional<glm::vec3> PbrtParams::get_illuminant(const std::string& name) {
    if (type_of(name) != "blackbody") {
        return get_rgb(name);
    }
    const PbrtParam* p = find(name, {"blackbody"});
    const std::vector<double> v = get_numbers(name, {"blackbody"}, 1);
    if (v.empty() || v.size() > 2) {
        fail("parameter " + declared(*p) +
             " expects one temperature in kelvin (or pbrt-v3's temperature and scale)");
    }
    const auto rgb = blackbody_rgb(v[0]);
    if (!rgb) {
        fail("parameter " + declared(*p) + ": " + excerpt(std::to_string(v[0])) +
             " K is not a temperature that emits visible light (give a positive kelvin value)");
    }
    return *rgb * static_cast<float>(v.size() == 2 ? v[1] : 1.0);
}

void PbrtParams::read_spectrum_files(const SceneFiles& files, std::filesystem::path dir) {
    spectrum_files_ = &files;
    spectrum_dir_ = std::move(dir);
}

std::vector<double> PbrtParams::spectrum_file_pairs(const PbrtParam& p) const {
    const std::string& name = p.strings[0];
    if (spectrum_files_ == nullptr) {
        refuse("parameter " + declared(p) + ": \"" + excerpt(name) +
               "\" is not one of pbrt-v4's named spectra radcache knows");
    }
    const std::filesystem::path given(name);
    const std::filesystem::path path = given.is_absolute() ? given : spectrum_dir_ / given;
    if (!spectrum_files_->exists(path)) {
        fail("parameter " + declared(p) + ": \"" + excerpt(name) +
             "\" is neither one of pbrt-v4's named spectra nor a file (" + excerpt(path.string()) +
             " not found)");
    }
    std::string text;
    try {
        text = spectrum_files_->read(path, kMaxMaterialFileBytes, "spectrum file");
    } catch (const Error& error) {
        fail("parameter " + declared(p) + ": " + error.what());
    }
    // pbrt-v4's float files: numbers separated by white space, '#' to the end of a line a comment.
    std::vector<double> pairs;
    size_t at = 0;
    while (at < text.size()) {
        const char c = text[at];
        if (c == '#') {
            at = text.find('\n', at);
            at = at == std::string::npos ? text.size() : at;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++at;
        } else {
            const size_t end = text.find_first_of(" \t\r\n#", at);
            const std::string word = text.substr(at, end == std::string::npos ? end : end - at);
            char* parsed_end = nullptr;
            const double value = std::strtod(word.c_str(), &parsed_end);
            if (parsed_end != word.c_str() + word.size() || !std::isfinite(value)) {
                fail("parameter " + declared(p) + ": spectrum file " + excerpt(path.string()) +
                     ": \"" + excerpt(word) + "\" is not a finite number");
            }
            pairs.push_back(value);
            at = end == std::string::npos ? text.size() : end;
        }
    }
    if (pairs.size() < 4 || pairs.size() % 2 != 0 || !sampled_spectrum_at(pairs, 550.0)) {
        fail("parameter " + declared(p) + ": spectrum file " + excerpt(path.string()) +
             " does not hold wavelength-value pairs with increasing wavelengths");
    }
    return pairs;
}

std::optional<glm::vec3> PbrtParams::get_material_spectrum(const std::string& name) {
    if (type_of(name) != "spectrum") {
        return get_rgb(name);
    }
    const PbrtParam* p = find(name, {"spectrum"});
    if (p->strings.size() == 1 && p->numbers.empty()) {
        if (const auto rgb = named_spectrum_rgb(p->strings[0])) {
            return rgb;
        }
        return sampled_spectrum_rgb(spectrum_file_pairs(*p));
    }
    const std::vector<double> v = get_numbers(name, {"spectrum"}, 1);
    if (v.size() == 1) {
        return glm::vec3(static_cast<float>(v[0]));
    }
    const auto rgb = sampled_spectrum_rgb(v);
    if (!rgb) {
        fail("parameter " + declared(*p) +
             " expects wavelength-value pairs with increasing wavelengths (or a name)");
    }
    return rgb;
}

std::optional<float> PbrtParams::get_index_of_refraction(const std::string& name) {
    if (type_of(name) != "spectrum") {
        if (!has(name)) {
            return std::nullopt;
        }
        return get_float(name, 1.0f);
    }
    const PbrtParam* p = find(name, {"spectrum"});
    if (p->strings.size() == 1 && p->numbers.empty()) {
        if (const auto ior = named_glass_ior(p->strings[0])) {
            return ior;
        }
        return static_cast<float>(*sampled_spectrum_at(spectrum_file_pairs(*p), 550.0));
    }
    const std::vector<double> v = get_numbers(name, {"spectrum"}, 1);
    if (v.size() == 1) {
        return static_cast<float>(v[0]);
    }
    const auto at = sampled_spectrum_at(v, 550.0);
    if (!at) {
        fail("parameter " + declared(*p) +
             " expects wavelength-value pairs with increasing "
             "wavelengths (or a name)");
    }
    return static_cast<float>(*at);
}

void PbrtParams::ignore(const std::string& name) {
    for (size_t i = 0; i < params_.size(); ++i) {
        if (params_[i].name == name) {
            used_[i] = true;
        }
    }
}

void PbrtParams::warn_unused() const {
    for (size_t i = 0; i < params_.size(); ++i) {
        if (!used_[i]) {
            log_warning(what_ + ": parameter " + declared(params_[i]) +
                        " is not supported and ignored");
        }
    }
}

}  // namespace rc
