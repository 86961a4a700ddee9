#include "scene/texture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace rc {
namespace {

float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

Texture load_texture(const std::filesystem::path& file) {
    if (!std::filesystem::is_regular_file(file)) {
        throw Error(file.string() + ": texture file not found");
    }
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(file.string());
    if (!in) {
        throw Error(file.string() + ": cannot read texture: " + OIIO::geterror());
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        throw Error(file.string() + ": texture has no pixels");
    }
    std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        throw Error(file.string() + ": cannot read texture: " + in->geterror());
    }
    const bool encoded = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                         spec.format.basetype == OIIO::TypeDesc::UINT16;
    Texture texture;
    texture.file = file;
    texture.width = spec.width;
    texture.height = spec.height;
    texture.texels.resize(static_cast<size_t>(spec.width) * spec.height);
    const int channels = spec.nchannels;
    for (size_t i = 0; i < texture.texels.size(); ++i) {
        glm::vec4 texel(0.0f, 0.0f, 0.0f, 1.0f);
        for (int c = 0; c < 3; ++c) {
            float value = pixels[i * channels + std::min(c, channels < 3 ? 0 : c)];
            if (encoded) {
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
