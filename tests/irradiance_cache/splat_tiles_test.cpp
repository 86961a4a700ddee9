// Radiance cache splatting's screen tiles (host/methods/caching/splat_tiles.h) against
// brute force: every sub-pixel camera ray (the camera's own definition in
// kernels/shared/types.h: direction top_left + right x / W + down y / H) that meets a record's
// influence sphere must fall in a tile that lists the record.
#include "methods/caching/splat_tiles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "scene/camera.h"

namespace rc {
namespace {

glm::vec3 vec3_of(const shared::float4& v) { return {v.x, v.y, v.z}; }

// Whether the ray from the eye through image position (x, y) meets the sphere (solid ball).
bool ray_meets_sphere(const shared::CameraParams& camera, float x, float y, glm::vec3 centre,
                      float radius) {
    const glm::vec3 eye = vec3_of(camera.origin);
    const glm::vec3 d = glm::normalize(vec3_of(camera.top_left) +
                                       vec3_of(camera.right) * (x / camera.resolution.x) +
                                       vec3_of(camera.down) * (y / camera.resolution.y));
    const glm::vec3 to_centre = centre - eye;
    const float along = glm::dot(to_centre, d);
    const float closest_squared = glm::dot(to_centre, to_centre) - along * along;
    if (closest_squared > radius * radius) {
        return false;
    }
    // The far intersection must lie in front of the eye.
    return along + std::sqrt(radius * radius - closest_squared) > 0.0f;
}

bool tile_lists(const SplatTiles& tiles, int px, int py, int record) {
    const size_t tile =
        static_cast<size_t>(py / tiles.tile_size) * tiles.tiles_x + px / tiles.tile_size;
    for (int i = tiles.tile_start[tile]; i < tiles.tile_start[tile + 1]; ++i) {
        if (tiles.tile_records[static_cast<size_t>(i)] == record) {
            return true;
        }
    }
    return false;
}

TEST(SplatTiles, EveryPixelThatSeesAnInfluenceSphereListsItsRecord) {
    Camera camera;
    camera.position = {0.3f, 0.2f, -4.0f};
    camera.look_at = {0.0f, 0.0f, 0.0f};
    camera.fov_degrees = 50.0f;
    const int width = 61;
    const int height = 47;
    const shared::CameraParams params = camera_params(camera, width, height);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
    std::vector<glm::vec3> centres;
    std::vector<float> radii;
    for (int k = 0; k < 60; ++k) {
        // Spheres in front, beside the frustum, and around the eye itself.
        centres.push_back(k % 10 == 9 ? vec3_of(params.origin) + 0.5f * glm::vec3(uniform(random))
                                      : glm::vec3(3.0f * uniform(random), 3.0f * uniform(random),
                                                  3.0f * uniform(random)));
        radii.push_back(0.02f + 0.6f * (0.5f + 0.5f * uniform(random)));
    }
    const SplatTiles tiles = splat_tiles(params, centres, radii, 8);
    size_t hits = 0;
    for (int py = 0; py < height; ++py) {
        for (int px = 0; px < width; ++px) {
            for (int sub = 0; sub < 16; ++sub) {  // 4 x 4 positions, pixel corners included
                const float x = px + (sub % 4) / 3.0f;
                const float y = py + (sub / 4) / 3.0f;
                for (int k = 0; k < static_cast<int>(centres.size()); ++k) {
                    if (ray_meets_sphere(params, std::min(x, width - 1e-3f),
                                         std::min(y, height - 1e-3f), centres[k], radii[k])) {
                        ++hits;
                        ASSERT_TRUE(tile_lists(tiles, px, py, k))
                            << "record " << k << " pixel " << px << ", " << py;
                    }
                }
            }
        }
    }
    EXPECT_GT(hits, 1000u);  // the spheres were seen
}

TEST(SplatTiles, ASmallSphereInFrontCoversAFewTilesInRecordOrder) {
    Camera camera;
    camera.position = {0.0f, 0.0f, -5.0f};
    const shared::CameraParams params = camera_params(camera, 128, 128);
    // Three small spheres on the optical axis's neighbourhood, and one behind the eye.
    const std::vector<glm::vec3> centres = {
        {0.0f, 0.0f, 0.0f}, {0.05f, 0.0f, 0.0f}, {0.0f, 0.0f, -9.0f}, {-0.05f, 0.0f, 0.0f}};
    const std::vector<float> radii = {0.1f, 0.1f, 0.1f, 0.1f};
    const SplatTiles tiles = splat_tiles(params, centres, radii, 8);
    const PixelRect rect = project_sphere(params, centres[0], radii[0]);
    // The sphere subtends about 2 atan(0.1 / 5) of a 45-degree field: ~7 pixels across.
    EXPECT_LE(rect.x1 - rect.x0 + 1, 12);
    EXPECT_LE(rect.y1 - rect.y0 + 1, 12);
    EXPECT_TRUE(project_sphere(params, centres[2], radii[2]).empty());
    for (size_t t = 0; t + 1 < tiles.tile_start.size(); ++t) {
        for (int i = tiles.tile_start[t]; i + 1 < tiles.tile_start[t + 1]; ++i) {
            EXPECT_LT(tiles.tile_records[i], tiles.tile_records[i + 1]);
        }
        for (int i = tiles.tile_start[t]; i < tiles.tile_start[t + 1]; ++i) {
            EXPECT_NE(tiles.tile_records[i], 2);
        }
    }
}

}  // namespace
}  // namespace rc
