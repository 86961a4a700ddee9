#include "methods/caching/splat_tiles.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rc {
namespace {

glm::vec3 vec3_of(const shared::float4& v) { return {v.x, v.y, v.z}; }

}  // namespace

PixelRect project_sphere(const shared::CameraParams& camera, glm::vec3 centre, float radius) {
    const int width = camera.resolution.x;
    const int height = camera.resolution.y;
    const PixelRect whole{0, 0, width - 1, height - 1};
    const glm::vec3 eye = vec3_of(camera.origin);
    const glm::vec3 top_left = vec3_of(camera.top_left);
    const glm::vec3 right = vec3_of(camera.right);
    const glm::vec3 down = vec3_of(camera.down);
    // The image plane is eye + top_left + right u + down v (u, v in [0, 1]); a point d from the
    // eye lies on the ray through (u, v) at d = s (top_left + right u + down v), s > 0.
    const glm::vec3 normal = glm::cross(right, down);
    const float plane = glm::dot(top_left, normal);
    if (!(std::isfinite(radius) && glm::distance(centre, eye) > radius)) {
        return whole;
    }
    // A pixel so narrow that the image plane's normal underflows (a field of view of 1e-30
    // degrees): no projection to trust, so every pixel may see the sphere.
    if (!(std::fabs(plane) > 0.0f && std::isfinite(plane))) {
        return whole;
    }
    // The corners of the sphere's bounding box: their projections' bounding rectangle holds the
    // sphere's (perspective maps the box, in front of the eye, to the hull of its corners).
    float x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY, y_max = -INFINITY;
    int behind = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 sign((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f,
                             (corner & 4) ? 1.0f : -1.0f);
        const glm::vec3 d = centre + radius * sign - eye;
        const float s = glm::dot(d, normal) / plane;
        if (!(s > 1e-6f * glm::length(d))) {
            ++behind;  // behind the eye (or on its plane): projects nowhere or everywhere
            continue;
        }
        const glm::vec3 on_plane = d / s - top_left;
        const float x = glm::dot(on_plane, right) / glm::dot(right, right) * width;
        const float y = glm::dot(on_plane, down) / glm::dot(down, down) * height;
        x_min = std::min(x_min, x);
        x_max = std::max(x_max, x);
        y_min = std::min(y_min, y);
        y_max = std::max(y_max, y);
    }
    if (behind == 8) {
        return PixelRect{};  // wholly behind the eye: seen by no pixel
    }
    if (behind > 0) {
        return whole;  // straddles the eye's plane
    }
    // One pixel of margin against rounding, and as many as a camera sample may lie beyond its
    // pixel (its pixel filter's radius past the pixel's half width); clipped to the image.
    const float margin = 1.0f + std::ceil(std::max(0.0f, camera.filter_radius - 0.5f));
    const auto clip = [](float value, int size) {
        return static_cast<int>(std::clamp(value, -1.0f, static_cast<float>(size)));
    };
    PixelRect rect;
    rect.x0 = std::max(0, clip(std::floor(x_min) - margin, width));
    rect.x1 = std::min(width - 1, clip(std::floor(x_max) + margin, width));
    rect.y0 = std::max(0, clip(std::floor(y_min) - margin, height));
    rect.y1 = std::min(height - 1, clip(std::floor(y_max) + margin, height));
    return rect;
}

SplatTiles splat_tiles(const shared::CameraParams& camera, const std::vector<glm::vec3>& centres,
                       const std::vector<float>& radii, int tile_size,
                       const std::vector<shared::TileDepths>* tile_depths) {
    SplatTiles tiles;
    tiles.tile_size = tile_size;
    tiles.tiles_x = (camera.resolution.x + tile_size - 1) / tile_size;
    tiles.tiles_y = (camera.resolution.y + tile_size - 1) / tile_size;
    const size_t count = static_cast<size_t>(tiles.tiles_x) * tiles.tiles_y;
    std::vector<PixelRect> rects(centres.size());
    std::vector<int> per_tile(count, 0);
    const glm::vec3 eye = vec3_of(camera.origin);
    std::vector<float> depth(centres.size());
    // Tiles of record k's rectangle whose sample depths its sphere overlaps: a sample p it
    // reaches has | |p - eye| - |c - eye| | <= |p - c| < r (with a margin for the rounding of
    // the two distances, computed on host and device).
    const auto for_each_tile = [&](size_t k, auto&& visit) {
        const PixelRect& rect = rects[k];
        const float margin = 1e-4f * (depth[k] + radii[k]);
        for (int ty = rect.y0 / tile_size; ty <= rect.y1 / tile_size; ++ty) {
            for (int tx = rect.x0 / tile_size; tx <= rect.x1 / tile_size; ++tx) {
                const size_t tile = static_cast<size_t>(ty) * tiles.tiles_x + tx;
                if (tile_depths == nullptr ||
                    (depth[k] - radii[k] - margin <= (*tile_depths)[tile].farthest &&
                     depth[k] + radii[k] + margin >= (*tile_depths)[tile].nearest)) {
                    visit(tile);
                }
            }
        }
    };
    // Counting sort by tile, records in order: count, prefix sums, fill.
    for (size_t k = 0; k < centres.size(); ++k) {
        rects[k] = project_sphere(camera, centres[k], radii[k]);
        depth[k] = glm::distance(centres[k], eye);
        if (!rects[k].empty()) {
            for_each_tile(k, [&](size_t tile) { ++per_tile[tile]; });
        }
    }
    tiles.tile_start.assign(count + 1, 0);
    for (size_t t = 0; t < count; ++t) {
        tiles.tile_start[t + 1] = tiles.tile_start[t] + per_tile[t];
    }
    tiles.tile_records.resize(static_cast<size_t>(tiles.tile_start[count]));
    std::vector<int> next(tiles.tile_start.begin(), tiles.tile_start.end() - 1);
    for (size_t k = 0; k < centres.size(); ++k) {
        if (!rects[k].empty()) {
            for_each_tile(k, [&](size_t tile) {
                tiles.tile_records[static_cast<size_t>(next[tile]++)] = static_cast<int>(k);
            });
        }
    }
    return tiles;
}

}  // namespace rc
