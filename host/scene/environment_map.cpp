#include "scene/environment_map.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "util/error.h"

namespace rc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The solid angle of row y's texels (all alike in both mappings): lat-long 2 pi / W (cos theta0 -
// cos theta1), equal-area 4 pi / (W H).
double texel_solid_angle(int mapping, int y, int width, int height) {
    if (mapping == RC_MAP_EQUAL_AREA) {
        return 4.0 * kPi / (static_cast<double>(width) * height);
    }
    const double theta0 = kPi * y / height;
    const double theta1 = kPi * (y + 1) / height;
    return 2.0 * kPi / width * (std::cos(theta0) - std::cos(theta1));
}

// The largest solid angle a unit of image area covers within row y (the density's smallest).
double largest_jacobian(int mapping, int y, int height) {
    if (mapping == RC_MAP_EQUAL_AREA) {
        return 4.0 * kPi;
    }
    const double theta0 = kPi * y / height;
    const double theta1 = kPi * (y + 1) / height;
    const double s =
        theta0 <= kPi / 2 && theta1 >= kPi / 2 ? 1.0 : std::max(std::sin(theta0), std::sin(theta1));
    return 2.0 * kPi * kPi * s;
}

void store_frame(const glm::mat3& m, shared::Light& light) {
    // glm is column-major: row r of m is (m[0][r], m[1][r], m[2][r]).
    light.map_x = {m[0][0], m[1][0], m[2][0], 0.0f};
    light.map_y = {m[0][1], m[1][1], m[2][1], 0.0f};
    light.map_z = {m[0][2], m[1][2], m[2][2], 0.0f};
}

}  // namespace

glm::vec3 add_environment_map(const Emitter& emitter, const Texture& texture,
                              std::vector<float>& cdf, shared::Light& light) {
    const int width = texture.width;
    const int height = texture.height;
    const int mapping = emitter.map_mapping;
    std::vector<double> row_weight(height, 0.0);
    std::vector<double> weights(static_cast<size_t>(width) * height, 0.0);
    glm::dvec3 sum(0.0);
    for (int y = 0; y < height; ++y) {
        const double omega = texel_solid_angle(mapping, y, width, height);
        for (int x = 0; x < width; ++x) {
            const glm::vec4& t = texture.texels[static_cast<size_t>(y) * width + x];
            const double w = (t.r + t.g + t.b) / 3.0 * omega;
            weights[static_cast<size_t>(y) * width + x] = w;
            row_weight[y] += w;
            sum += glm::dvec3(t.r, t.g, t.b) * omega;
        }
    }
    double total = 0.0;
    for (double w : row_weight) {
        total += w;
    }
    if (!(total > 0.0)) {
        throw Error("the environment map " + emitter.map_file + " is black everywhere");
    }
    light.map = emitter.map;
    light.map_mapping = mapping;
    light.map_distribution = static_cast<int>(cdf.size());
    store_frame(emitter.map_from_world, light);
    double running = 0.0;
    for (int y = 0; y < height; ++y) {
        running += row_weight[y];
        cdf.push_back(y + 1 == height ? 1.0f : static_cast<float>(running / total));
    }
    double largest = 0.0;
    for (int y = 0; y < height; ++y) {
        double in_row = 0.0;
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            in_row += weights[i];
            cdf.push_back(x + 1 == width || row_weight[y] <= 0.0
                              ? (x + 1 == width ? 1.0f : 0.0f)
                              : static_cast<float>(in_row / row_weight[y]));
            if (weights[i] > 0.0) {
                // The texel's density in image area is p W H; its solid-angle density is that
                // over the Jacobian, least where the Jacobian is largest.
                const glm::vec4& t = texture.texels[i];
                const double p = weights[i] / total * width * height;
                const double ratio =
                    std::max({t.r, t.g, t.b}) * largest_jacobian(mapping, y, height) / p;
                largest = std::max(largest, ratio);
            }
        }
    }
    const glm::vec3 mean = glm::vec3(sum / (4.0 * kPi));
    light.radiance = {mean.x, mean.y, mean.z, 0.0f};
    light.area = static_cast<float>(largest);
    return mean;
}

void load_environment_map(Scene& scene, Emitter& emitter, const std::filesystem::path& file,
                          const SceneFiles& files, glm::vec3 scale, int mapping) {
    Texture texture = load_texture(file, files);
    if (mapping == RC_MAP_EQUAL_AREA && texture.width != texture.height) {
        throw Error(file.string() + ": an equal-area environment map must be square, not " +
                    std::to_string(texture.width) + " x " + std::to_string(texture.height));
    }
    // Radiance is not negative (pbrt-v4 clamps an RGB illuminant at zero); a texel that is not
    // finite would make every sample's density NaN.
    for (size_t i = 0; i < texture.texels.size(); ++i) {
        glm::vec4& t = texture.texels[i];
        const glm::vec3 radiance = glm::max(glm::vec3(t), glm::vec3(0.0f)) * scale;
        if (!std::isfinite(radiance.x + radiance.y + radiance.z)) {
            throw Error(file.string() + ": environment map texel (" +
                        std::to_string(i % static_cast<size_t>(texture.width)) + ", " +
                        std::to_string(i / static_cast<size_t>(texture.width)) +
                        ") is not finite (times the scale)");
        }
        t = glm::vec4(radiance, 1.0f);
    }
    texture.max_value *= std::max({scale.x, scale.y, scale.z});
    emitter.kind = EmitterKind::kConstant;
    emitter.radiance = glm::vec3(1.0f);
    emitter.map = static_cast<int>(scene.textures.size());
    emitter.map_mapping = mapping;
    emitter.map_file = file.string();
    emitter.map_scale = scale;
    scene.textures.push_back(std::move(texture));
}

const char* map_mapping_name(int mapping) {
    return mapping == RC_MAP_EQUAL_AREA ? "equal-area" : "latlong";
}

int map_mapping_of(const std::string& name) {
    if (name == "latlong") {
        return RC_MAP_LATLONG;
    }
    if (name == "equal-area") {
        return RC_MAP_EQUAL_AREA;
    }
    return -1;
}

}  // namespace rc
