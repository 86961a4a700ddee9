// A float image in scene-linear RGB(A), rows top to bottom.
#pragma once

#include <string>
#include <vector>

namespace rc {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;  // width * height * channels, interleaved
    std::vector<std::string> channel_names;

    Image() = default;
    Image(int width, int height, int channels);

    float& at(int x, int y, int c) {
        return pixels[(static_cast<size_t>(y) * width + x) * channels + c];
    }
    float at(int x, int y, int c) const {
        return pixels[(static_cast<size_t>(y) * width + x) * channels + c];
    }
};

}  // namespace rc
