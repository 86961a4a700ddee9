#include "glossy_scenes.h"

#include <cmath>
#include <cstring>
#include <fstream>

#include "scene/scene_loader.h"
#include "test_support.h"

namespace rc::test {

// relMSE ((v - r)^2 / (r^2 + 0.01), image_error's) of layer `layer` of `image` over the pixels
// where `mask`'s first channel is positive; *pixels their count.
double masked_relmse(const Image& image, const Image& reference, const Image& mask,
                     size_t* pixels) {
    double sum = 0.0;
    *pixels = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (!(mask.at(x, y, 0) > 0.0f)) {
                continue;
            }
            ++*pixels;
            for (int c = 0; c < image.channels; ++c) {
                const double r = reference.at(x, y, c);
                const double d = image.at(x, y, c) - r;
                sum += d * d / (r * r + 0.01);
            }
        }
    }
    return *pixels > 0 ? sum / (*pixels * image.channels) : 0.0;
}

Scene phong_sphere_scene(int exponent, const std::string& owner) {
    const auto dir = scratch_dir(owner + "_phong_" + std::to_string(exponent));
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 0.2, -3.4], "look_at": [0, -0.4, 0], "up": [0, 1, 0],
                   "fov": 24, "resolution": [32, 32]},
        "materials": {
            "white": {"type": "diffuse", "reflectance": 0.5},
            "red": {"type": "diffuse", "reflectance": [0.7, 0.1, 0.1]},
            "blue": {"type": "diffuse", "reflectance": [0.1, 0.15, 0.7]},
            "sphere": {"type": "phong", "diffuse": 0.1, "specular": 0.6, "exponent": )"
                                      << exponent << R"(}},
        "shapes": [
            {"type": "rectangle", "material": "white",
             "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"translate": [0, -1, 0]}]},
            {"type": "rectangle", "material": "white",
             "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"translate": [0, 1, 0]}]},
            {"type": "rectangle", "material": "white",
             "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 180}}, {"translate": [0, 0, 1]}]},
            {"type": "rectangle", "material": "red",
             "transform": [{"rotate": {"axis": [0, 1, 0], "angle": -90}}, {"translate": [1, 0, 0]}]},
            {"type": "rectangle", "material": "blue",
             "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 90}}, {"translate": [-1, 0, 0]}]},
            {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 12},
             "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 0.998, 0]}]},
            {"type": "sphere", "center": [0, -0.55, 0], "radius": 0.45, "material": "sphere"}
        ]
    })";
    return load_scene(dir / "scene.json");
}

// The pixels all of whose camera samples see the sphere (albedo 0.7 in every channel: the
// walls' are 0.5 or coloured).
Image sphere_mask(const Image& albedo) {
    Image mask(albedo.width, albedo.height, 1);
    for (int y = 0; y < albedo.height; ++y) {
        for (int x = 0; x < albedo.width; ++x) {
            bool sphere = true;
            for (int c = 0; c < 3; ++c) {
                sphere = sphere && std::abs(albedo.at(x, y, c) - 0.7f) < 1e-4f;
            }
            mask.at(x, y, 0) = sphere ? 1.0f : 0.0f;
        }
    }
    return mask;
}

bool bitwise_equal(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

}  // namespace rc::test
