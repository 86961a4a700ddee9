// Radiance cache splatting's image side (course, "Radiance Cache Splatting", §4.1 Algorithm 1):
// every record's influence sphere I_k (centre p_k, radius a R_k, eq. 4) is projected onto the
// image plane, and its bounding rectangle is splatted into the screen tiles it covers. A tile's
// list keeps its records in record order, so the splat kernel (kernels: ic_splat) accumulates
// each camera sample's (sum w E', sum w) in that order: what ordered blending of the records'
// quads gives on a GPU's raster pipeline, deterministic without atomics.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "shared/records.h"
#include "shared/types.h"

namespace rc {

// Pixels [x0, x1] x [y0, y1] (inclusive); empty when x0 > x1 or y0 > y1.
struct PixelRect {
    int x0 = 0;
    int y0 = 0;
    int x1 = -1;
    int y1 = -1;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

// A rectangle of pixels holding every pixel through which the sphere (centre, radius) can be
// seen by `camera`, clipped to its image (one pixel of margin; the whole image when the sphere
// reaches behind the eye).
PixelRect project_sphere(const shared::CameraParams& camera, glm::vec3 centre, float radius);

// Records binned by screen tile: tile t lists records[tile_start[t] .. tile_start[t + 1]) of
// tile_records, ascending.
struct SplatTiles {
    int tile_size = 8;  // pixels per tile side
    int tiles_x = 0;
    int tiles_y = 0;
    std::vector<int> tile_start;    // tiles + 1 entries
    std::vector<int> tile_records;  // record indices, tile by tile
};

// Splats the influence spheres (centres[k], radii[k]) of records 0 .. n-1 into tiles of
// `tile_size` pixels of the camera's image. With `tile_depths` (per tile, the nearest and
// farthest distance from the eye of the samples it holds, as ic_tile_depths gives them) a record
// is left out of the tiles whose depths its sphere does not overlap (a depth test: no sample
// there lies within its radius).
SplatTiles splat_tiles(const shared::CameraParams& camera, const std::vector<glm::vec3>& centres,
                       const std::vector<float>& radii, int tile_size = RC_SPLAT_TILE_SIZE,
                       const std::vector<shared::TileDepths>* tile_depths = nullptr);

}  // namespace rc
