// Image textures, read with OpenImageIO into linear RGB.
#pragma once

#include <filesystem>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "scene/scene_files.h"

namespace rc {

struct Texture {
    std::filesystem::path file;
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> texels;  // linear RGB (a = 1), rows top to bottom
    float max_value = 0.0f;         // largest RGB component
    // The image file's bytes when the texture came from inside a glTF file (embedded or not;
    // `radcache convert` writes them out); empty otherwise.
    std::string encoded;
    // Baked from a procedural texture (a pbrt checkerboard): no file holds it, `file` names its
    // definition.
    bool procedural = false;
};

// Reads the image through `files` (within image/image_io.h's limits); 8- and 16-bit integer images
// are taken as sRGB-encoded and decoded to linear, float images as linear. Grey images are
// expanded to RGB. Throws Error naming the file.
Texture load_texture(const std::filesystem::path& file, const SceneFiles& files = disk_files());
// The same from an image file's bytes; `name`'s extension picks the format and names it in errors.
Texture decode_texture(const std::string& bytes, const std::filesystem::path& name);

}  // namespace rc
