#include "glossy_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "box_walls.h"
#include "scene/scene_loader.h"
#include "sh_quadrature.h"
#include "test_support.h"
#include "util/glm_helpers.h"

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

std::string glossy_box_json(int fov, const std::string& materials, const std::string& shapes) {
    BoxWalls walls;
    walls.right = "red";
    walls.left = "blue";
    return R"({
        "camera": {"position": [0, 0.2, -3.4], "look_at": [0, -0.4, 0], "up": [0, 1, 0],
                   "fov": )" +
           std::to_string(fov) + R"(, "resolution": [32, 32]},
        "materials": {
            "white": {"type": "diffuse", "reflectance": 0.5},
            "red": {"type": "diffuse", "reflectance": [0.7, 0.1, 0.1]},
            "blue": {"type": "diffuse", "reflectance": [0.1, 0.15, 0.7]},
            )" +
           materials + R"(
        },
        "shapes": [)" +
           box_walls_json(walls) + R"(,
            {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 12},
             "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 0.998, 0]}]},
            )" +
           shapes + R"(
        ]
    })";
}

Scene phong_sphere_scene(int exponent, const std::string& owner) {
    const auto dir = scratch_dir(owner + "_phong_" + std::to_string(exponent));
    std::ofstream(dir / "scene.json") << glossy_box_json(
        24,
        R"("sphere": {"type": "phong", "diffuse": 0.1, "specular": 0.6, "exponent": )" +
            std::to_string(exponent) + "}",
        R"({"type": "sphere", "center": [0, -0.55, 0], "radius": 0.45, "material": "sphere"})");
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

Scene sky_plane_scene(const std::string& name, const std::string& eye, const std::string& material,
                      const std::string& sky) {
    const auto dir = scratch_dir(name);
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": )" << eye
                                      << R"(, "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 30,
                   "resolution": [16, 16]},
        "materials": {"glossy": )" << material
                                      << R"(},
        "shapes": [{"type": "rectangle", "material": "glossy",
                    "transform": [{"scale": 1000}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]}],
        "emitters": [{"type": "constant", "radiance": )"
                                      << sky << R"(}]
    })";
    return load_scene(dir / "scene.json");
}

RelativeErrors sky_plane_errors(
    const Image& glossy, const Camera& camera, const Material& material,
    const std::array<double, 3>& sky,
    const std::function<void(int x, int y, int c, double error, double expected)>& check) {
    const shared::CameraParams params = camera_params(camera, glossy.width, glossy.height);
    RelativeErrors errors;
    for (int y = 0; y < glossy.height; ++y) {
        for (int x = 0; x < glossy.width; ++x) {
            const glm::vec3 d = glm::normalize(vec3_of(params.top_left) +
                                               vec3_of(params.right) * ((x + 0.5f) / glossy.width) +
                                               vec3_of(params.down) * ((y + 0.5f) / glossy.height));
            // The plane's frame: its normal +y is z; w_o = -d.
            const shared::float4 wo = {-d.x, -d.z, -d.y, 0.0f};
            const double albedo = record_hemisphere_albedo(shared_context(), material, wo);
            for (int c = 0; c < 3; ++c) {
                const double expected = sky[c] * albedo;
                const double error = glossy.at(x, y, c) / expected - 1.0;
                errors.largest = std::max(errors.largest, std::abs(error));
                errors.mean += error / (3 * glossy.width * glossy.height);
                check(x, y, c, error, expected);
            }
        }
    }
    return errors;
}

}  // namespace rc::test
