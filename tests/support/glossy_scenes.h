// Shared pieces of the glossy caches' tests (rc_method_test, sdrc_method_test): a sphere of a
// given Phong exponent in a coloured box, the mask of its pixels, a masked relMSE, and bitwise
// image equality.
#pragma once

#include <cstddef>
#include <string>

#include "image/image.h"
#include "scene/scene.h"

namespace rc::test {

// relMSE ((v - r)^2 / (r^2 + 0.01), image_error's) of `image` against `reference` over the pixels
// where `mask`'s first channel is positive; *pixels their count.
double masked_relmse(const Image& image, const Image& reference, const Image& mask, size_t* pixels);

// A sphere of Phong exponent `exponent` (diffuse 0.1, specular 0.6) on a white floor in a box
// with a red and a blue wall, lit by a small area light, 32 x 32: its glossy reflection of the
// walls is indirect light. Written to the scratch folder `owner`_phong_`exponent` (one per test
// program: they run in parallel).
Scene phong_sphere_scene(int exponent, const std::string& owner);

// The pixels all of whose camera samples see that sphere (albedo 0.7 in every channel: the
// walls' are 0.5 or coloured), from the albedo layer.
Image sphere_mask(const Image& albedo);

bool bitwise_equal(const Image& a, const Image& b);

}  // namespace rc::test
