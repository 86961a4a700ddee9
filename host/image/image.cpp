#include "image/image.h"

#include <algorithm>

#include "util/error.h"

namespace rc {

Image::Image(int w, int h, int c)
    : width(w), height(h), channels(c), pixels(static_cast<size_t>(w) * h * c, 0.0f) {
    static const char* kNames[] = {"R", "G", "B", "A"};
    for (int i = 0; i < c; ++i) {
        channel_names.push_back(i < 4 ? kNames[i] : "C" + std::to_string(i));
    }
}

namespace {

std::string layer_of(const std::string& channel) {
    const size_t dot = channel.rfind('.');
    return dot == std::string::npos ? "beauty" : channel.substr(0, dot);
}

}  // namespace

Image box_filtered(const Image& image, int factor) {
    Image out(image.width / factor, image.height / factor, image.channels);
    out.channel_names = image.channel_names;
    const double weight = 1.0 / (static_cast<double>(factor) * factor);
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            for (int c = 0; c < image.channels; ++c) {
                double sum = 0.0;
                for (int j = 0; j < factor; ++j) {
                    for (int i = 0; i < factor; ++i) {
                        sum += image.at(factor * x + i, factor * y + j, c);
                    }
                }
                out.at(x, y, c) = static_cast<float>(sum * weight);
            }
        }
    }
    return out;
}

std::vector<std::string> layer_names(const Image& image) {
    std::vector<std::string> names;
    for (const std::string& channel : image.channel_names) {
        const std::string layer = layer_of(channel);
        if (std::find(names.begin(), names.end(), layer) == names.end()) {
            names.push_back(layer);
        }
    }
    return names;
}

Image select_layers(const Image& image, const std::vector<std::string>& layers) {
    std::vector<int> channels;
    for (const std::string& layer : layers) {
        const size_t before = channels.size();
        for (int c = 0; c < image.channels; ++c) {
            if (layer_of(image.channel_names[c]) == layer) {
                channels.push_back(c);
            }
        }
        if (channels.size() == before) {
            std::string known;
            for (const std::string& name : layer_names(image)) {
                known += (known.empty() ? "" : ", ") + name;
            }
            throw Error("the image has no layer '" + layer + "' (it has " + known + ")", 2);
        }
    }
    Image selected(image.width, image.height, static_cast<int>(channels.size()));
    selected.channel_names.clear();
    for (int c : channels) {
        selected.channel_names.push_back(image.channel_names[c]);
    }
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t k = 0; k < channels.size(); ++k) {
            selected.pixels[p * channels.size() + k] =
                image.pixels[p * image.channels + channels[k]];
        }
    }
    return selected;
}

}  // namespace rc
