// pbrt-v4's scene description read into a flat list of directives with their arguments and
// typed parameter lists (docs/importing.md#pbrt-v4-import). Include and Import are followed
// here, in place, relative to the main file's folder (as pbrt resolves them), so the list is
// the whole scene in reading order. The meaning of the directives is scene/pbrt_loader.cpp's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_files.h"

namespace rc {

// One parameter: "type name" and its values (numbers, or strings: bools are "true"/"false").
struct PbrtParam {
    std::string type;  // as declared: "float", "rgb", "point3", "texture", ...
    std::string name;
    std::vector<double> numbers;
    std::vector<std::string> strings;
    bool is_bool = false;  // strings holds "true"/"false"
};

struct PbrtDirective {
    std::string name;  // "Shape", "LookAt", ...
    std::string file;
    int line = 0;
    std::vector<double> numbers;       // Translate, LookAt, Transform, ...
    std::vector<std::string> strings;  // the type or name arguments: Shape "trianglemesh", ...
    std::vector<PbrtParam> params;

    // "file:line".
    std::string where() const { return file + ":" + std::to_string(line); }
};

// The directives of `path` and of the files it includes; Error "file:line: ..." for a
// malformed file, an unknown directive or parameter type, a value of the wrong type, a missing
// or cyclic Include.
std::vector<PbrtDirective> parse_pbrt_file(const std::filesystem::path& path,
                                           const SceneFiles& files);

// Whether `path` names a pbrt-v4 scene (.pbrt, any case).
bool is_pbrt_path(const std::filesystem::path& path);

}  // namespace rc
