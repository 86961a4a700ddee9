#include "methods/method.h"

#include <algorithm>

namespace rc {

bool MethodSettings::writes_layer(const std::string& layer) const {
    return layers.empty() || std::find(layers.begin(), layers.end(), layer) != layers.end();
}

}  // namespace rc
