// Typed access to a pbrt-v4 directive's parameter list (scene/pbrt_parser.h), as pbrt's
// ParameterDictionary gives it: a value by name with a default, its type checked. Every
// parameter read is marked; those left unread are warned about by name (pbrt refuses them), so
// nothing in the file is dropped without a word.
#pragma once

#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/pbrt_parser.h"
#include "scene/scene_files.h"

namespace rc {

class PbrtParams {
   public:
    // `what` names the directive in messages: "scene.pbrt:12: Shape \"trianglemesh\"".
    PbrtParams(const PbrtDirective& directive, std::string what);

    const std::string& what() const { return what_; }
    // Lets a "spectrum" parameter name a spectrum file (pbrt-v4's .spd: wavelength-value pairs),
    // read from `files` relative to `dir` (the scene file's folder) when no named spectrum has
    // its name.
    void read_spectrum_files(const SceneFiles& files, std::filesystem::path dir);
    bool has(const std::string& name) const;
    // The parameter's declared type ("" when absent); does not mark it read.
    std::string type_of(const std::string& name) const;

    float get_float(const std::string& name, float fallback);
    int get_int(const std::string& name, int fallback);
    bool get_bool(const std::string& name, bool fallback);
    std::string get_string(const std::string& name, const std::string& fallback);
    std::optional<glm::vec3> get_point3(const std::string& name);
    // All values of a float, integer, point3, normal3 or point2 array ("point3 P", "integer
    // indices"), checked to be a whole number of `width`-tuples.
    std::vector<double> get_numbers(const std::string& name, const std::vector<std::string>& types,
                                    size_t width);
    // An "rgb" (or pbrt-v3 "color") spectrum; blackbody and sampled spectra are refused.
    std::optional<glm::vec3> get_rgb(const std::string& name);
    // A light's spectrum as linear sRGB: "rgb" (or "color"), or "blackbody" [T] (kelvin; pbrt-v3's
    // [T scale] too), its luminance made 1 as pbrt-v4 normalises a light's spectrum.
    std::optional<glm::vec3> get_illuminant(const std::string& name);
    // A material's spectrum as linear sRGB: "rgb" (or "color"), or a "spectrum" given by one of
    // pbrt-v4's names (named_spectra.h), a spectrum file (read_spectrum_files), as
    // wavelength-value pairs, or as one constant; blackbody spectra are refused.
    std::optional<glm::vec3> get_material_spectrum(const std::string& name);
    // The parameter's one value at 550 nm: a "float", a named glass, a spectrum file or a sampled
    // "spectrum" (an index of refraction, which radcache renders without dispersion).
    std::optional<float> get_index_of_refraction(const std::string& name);
    // Marks the parameter read without using it (a parameter the import may ignore).
    void ignore(const std::string& name);

    // Warns about every parameter no getter read: "<what>: parameter \"float foo\" is not
    // supported and ignored".
    void warn_unused() const;
    // Error "<what>: <message>" for a malformed value (exit status 1).
    [[noreturn]] void fail(const std::string& message) const;
    // The same for a well-formed request radcache does not do (exit status 2, kExitUnsupported).
    [[noreturn]] void refuse(const std::string& message) const;

   private:
    const PbrtParam* find(const std::string& name, const std::vector<std::string>& types);
    // find() for a parameter of one value: one number, or one string when `strings`; a parameter
    // with another count fails, saying it `expects` ("one integer").
    const PbrtParam* find_single(const std::string& name, const std::vector<std::string>& types,
                                 bool strings, const std::string& expects);

    // The wavelength-value pairs of the spectrum file parameter p names (its one string).
    std::vector<double> spectrum_file_pairs(const PbrtParam& p) const;

    std::vector<PbrtParam> params_;
    std::vector<bool> used_;
    std::string what_;
    const SceneFiles* spectrum_files_ = nullptr;
    std::filesystem::path spectrum_dir_;
};

}  // namespace rc
