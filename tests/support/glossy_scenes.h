// Shared pieces of the glossy caches' tests (rc_method_test, sdrc_method_test): a sphere of a
// given Phong exponent in a coloured box, the mask of its pixels, a masked relMSE, bitwise image
// equality, and a glossy plane under a constant sky with what it must reflect.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>

#include "image/image.h"
#include "scene/camera.h"
#include "scene/material.h"
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

// The scene.json of that box: the camera (vertical field of view `fov` degrees, 32 x 32), the
// white, red and blue diffuse materials and `materials` (JSON members, each "name": {...}), the
// walls (red right, blue left), the small area light and `shapes` (JSON array members).
std::string glossy_box_json(int fov, const std::string& materials, const std::string& shapes);

// The pixels all of whose camera samples see that sphere (albedo 0.7 in every channel: the
// walls' are 0.5 or coloured), from the albedo layer.
Image sphere_mask(const Image& albedo);

bool bitwise_equal(const Image& a, const Image& b);

// The plane y = 0 (2000 across) of material JSON `material` under a constant sky of radiance
// `sky` (JSON), nothing else, seen from `eye` (JSON) looking at the origin (fov 30, 16 x 16).
// Written to the scratch folder `name`.
Scene sky_plane_scene(const std::string& name, const std::string& eye, const std::string& material,
                      const std::string& sky);

struct RelativeErrors {
    double largest = 0.0;  // in magnitude
    double mean = 0.0;
};

// The glossy-indirect layer `glossy` of such a plane (`material`, sky radiance `sky`) seen by
// `camera` against what it must be, sky x albedo(w_o) (w_o: the direction to the camera through
// the pixel's centre; the albedo, record_hemisphere_albedo in the plane's frame): check(x, y, c,
// relative error, expected) for each pixel and channel, and the largest and mean relative error.
RelativeErrors sky_plane_errors(
    const Image& glossy, const Camera& camera, const Material& material,
    const std::array<double, 3>& sky,
    const std::function<void(int x, int y, int c, double error, double expected)>& check);

}  // namespace rc::test
