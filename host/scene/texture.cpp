#include "scene/texture.h"

#include <algorithm>
#include <cmath>

#include "image/image_io.h"
#include "util/error.h"

namespace rc {
namespace {

float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

Texture load_texture(const std::filesystem::path& file, const SceneFiles& files) {
    if (!files.exists(file)) {
        throw Error(file.string() + ": texture file not found");
    }
    return decode_texture(files.read(file, kMaxTextureFileBytes, "texture"), file);
}

Texture decode_texture(const std::string& bytes, const std::filesystem::path& file) {
    const DecodedImage decoded = decode_image(bytes, file.string());
    const Image& image = decoded.image;
    Texture texture;
    texture.file = file;
    texture.width = image.width;
    texture.height = image.height;
    texture.texels.resize(static_cast<size_t>(image.width) * image.height);
    const int channels = image.channels;
    for (size_t i = 0; i < texture.texels.size(); ++i) {
        glm::vec4 texel(0.0f, 0.0f, 0.0f, 1.0f);
        for (int c = 0; c < 3; ++c) {
            float value = image.pixels[i * channels + std::min(c, channels < 3 ? 0 : c)];
            if (decoded.integer_encoded) {
                value = srgb_decode(value);
            }
            if (!std::isfinite(value) || value < 0.0f) {
                throw Error(file.string() + ": texel " + std::to_string(i) +
                            " is negative or not finite");
            }
            texel[c] = value;
            texture.max_value = std::max(texture.max_value, value);
        }
        texture.texels[i] = texel;
    }
    return texture;
}

}  // namespace rc
