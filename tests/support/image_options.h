// A method's options for a small test image: the settings every method shares (SharedSettings)
// that the tests set first.
#pragma once

#include <cstdint>
#include <type_traits>

#include "methods/shared_settings.h"

namespace rc::test {

// `Options` (a method's options, derived from SharedSettings) for a width x height image with
// `spp` camera samples per pixel and seed `seed`, every other setting at its default.
template <class Options>
Options image_options(int width, int height, int spp, uint64_t seed = 0) {
    static_assert(std::is_base_of_v<SharedSettings, Options>);
    Options options;
    options.width = width;
    options.height = height;
    options.spp = spp;
    options.seed = seed;
    return options;
}

}  // namespace rc::test
