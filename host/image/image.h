// A float image in scene-linear RGB(A), rows top to bottom.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rc {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;  // width * height * channels, interleaved
    std::vector<std::string> channel_names;
    // .exr: where the pixels lie in a larger image (its data window's origin and its display
    // window's size; full_width 0: the image is whole), and string attributes written and read
    // as they are (`radcache merge` reads a part's "radcache:*" attributes).
    int origin_x = 0;
    int origin_y = 0;
    int full_width = 0;
    int full_height = 0;
    std::map<std::string, std::string> metadata;

    Image() = default;
    Image(int width, int height, int channels);

    float& at(int x, int y, int c) {
        return pixels[(static_cast<size_t>(y) * width + x) * channels + c];
    }
    float at(int x, int y, int c) const {
        return pixels[(static_cast<size_t>(y) * width + x) * channels + c];
    }
};

// The channels of the named layers, in the order given: "beauty" is the channels without a
// layer prefix (R, G, B), any other name the channels "name.*". Throws Error for a layer the
// image does not have.
Image select_layers(const Image& image, const std::vector<std::string>& layers);

// The image box-filtered by `factor` on both axes: each output pixel the mean of factor x factor
// input pixels (a box-filtered render at factor times the resolution gives the box-filtered
// render at this one); a width or height not divisible by factor loses its last pixels.
Image box_filtered(const Image& image, int factor);

// The layer names of an image, in channel order ("beauty" for unprefixed channels).
std::vector<std::string> layer_names(const Image& image);

}  // namespace rc
