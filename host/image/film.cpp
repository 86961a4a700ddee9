#include "image/film.h"

namespace rc {

Image unpack_film(const std::vector<shared::float4>& film, int slots, int width, int height,
                  const std::vector<FilmLayer>& layers) {
    int channels = 0;
    std::vector<std::string> names;
    for (const FilmLayer& layer : layers) {
        const char* const rgb[3] = {"R", "G", "B"};
        for (int c = 0; c < layer.channels; ++c) {
            const std::string channel = layer.channels == 1 ? "Y" : rgb[c];
            names.push_back(layer.name == "beauty" ? channel : layer.name + "." + channel);
        }
        channels += layer.channels;
    }
    Image image(width, height, channels);
    image.channel_names = names;
    const size_t pixels = static_cast<size_t>(width) * height;
    for (size_t p = 0; p < pixels; ++p) {
        const shared::float4* s = &film[static_cast<size_t>(slots) * p];
        float* out = &image.pixels[p * channels];
        for (const FilmLayer& layer : layers) {
            const float values[3] = {s[layer.slot].x, s[layer.slot].y, s[layer.slot].z};
            for (int c = 0; c < layer.channels; ++c) {
                *out++ = values[c];
            }
        }
    }
    return image;
}

}  // namespace rc
