#include "image/image.h"

namespace rc {

Image::Image(int w, int h, int c)
    : width(w), height(h), channels(c), pixels(static_cast<size_t>(w) * h * c, 0.0f) {
    static const char* kNames[] = {"R", "G", "B", "A"};
    for (int i = 0; i < c; ++i) {
        channel_names.push_back(i < 4 ? kNames[i] : "C" + std::to_string(i));
    }
}

}  // namespace rc
