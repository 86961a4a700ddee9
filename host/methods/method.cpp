#include "methods/method.h"

#include <algorithm>

namespace rc {

bool MethodSettings::writes_layer(const std::string& layer) const {
    return layers.empty() || std::find(layers.begin(), layers.end(), layer) != layers.end();
}

size_t image_pixels(int width, int height, const Scene& scene) {
    return static_cast<size_t>(width > 0 ? width : scene.camera.width) *
           static_cast<size_t>(height > 0 ? height : scene.camera.height);
}

}  // namespace rc
