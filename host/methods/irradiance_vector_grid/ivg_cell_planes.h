// Per cell of the irradiance vector grid, the one plane of the triangles that can block a
// lookup's shadow rays, when they lie in one (kernels/irradiance_vector_grid/ivg_visibility.h
// skips the shadow rays that plane proves unblocked). Built on the host with the grid, from the
// scene's triangles: each triangle's bounding box rasterised to cells, then an exact
// triangle-box test (triangle_box_overlap.h) against the cell grown by twice the cell margin.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc {

struct IvgCellPlanes {
    std::vector<int32_t> cell_planes;      // per cell (x fastest, then y, z): into planes, or -1
    std::vector<shared::IvgPlane> planes;  // the distinct planes the cells use
    float cell_margin = 0.0f;              // IvgParams::cell_margin
    float origin_margin = 0.0f;            // IvgParams::origin_margin
    size_t empty_cells = 0;                // no triangle overlaps them
    size_t multi_plane_cells = 0;          // triangles of several planes overlap them
};

// The cells of the grid `params` places, classified against `mesh` (the scene posed at the grid's
// frame; the triangles the BVH holds). Deterministic: cells take the plane of their first
// overlapping triangle in mesh order.
IvgCellPlanes classify_cell_planes(const TriangleMesh& mesh, const shared::IvgParams& params);

}  // namespace rc
