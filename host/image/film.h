// A render pass's film (float4 slots per pixel, kernels/shared/film.h) read back into an image.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "shared/compat.h"

namespace rc {

// One layer of the image and the film slot it comes from. "beauty" gives the channels R, G, B;
// any other name "name.R", "name.G", "name.B", or, with one channel, "name.Y".
struct FilmLayer {
    std::string name;
    int slot = 0;
    int channels = 3;  // 3: the slot's x, y, z; 1: its x
};

// The image of `film` (`slots` float4 per pixel, pixel p's slot k at p * slots + k): the layers'
// channels in the order given.
Image unpack_film(const std::vector<shared::float4>& film, int slots, int width, int height,
                  const std::vector<FilmLayer>& layers);

}  // namespace rc
