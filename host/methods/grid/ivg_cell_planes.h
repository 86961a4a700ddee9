// Per cell of the irradiance vector grid, up to two supporting planes of the triangles that can
// block a lookup's shadow rays: planes of the cell's triangles with every triangle of the cell on
// one side (on the plane or behind it), stored oriented towards the free side; a cell whose
// triangles all lie in one plane has it twice, once per side. A shadow ray whose two ends lie
// strictly on a free side meets none of them (kernels/common/ivg_visibility.h
// skips it). Built on the host with the grid, from the scene's triangles: each triangle's
// bounding box rasterised to cells, then an exact triangle-box test (triangle_box_overlap.h)
// against the cell grown by twice the cell margin.
//
// The work is bounded near-linearly in the triangles and cells: a triangle with bitwise the same
// vertices (in the same order) as an earlier one is left out (it changes no cell's classification),
// and at most kIvgBoxTestsPerElement triangle-box tests per distinct triangle and per cell are made
// in all. A triangle whose cells would overrun that budget is skipped, and every cell its bounding
// box reaches gets no plane (an unsupported cell: the kernel traces each corner's shadow ray, so
// the lookup stays exact, only slower). No ordinary scene comes near the budget.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/triangle_mesh.h"
#include "shared/types.h"

namespace rc {

struct IvgCellPlanes {
    std::vector<shared::IvgCellPlanes> cell_planes;  // per cell (x fastest, then y, z)
    std::vector<shared::IvgPlane> planes;            // the oriented planes the cells use
    float cell_margin = 0.0f;                        // IvgParams::cell_margin
    float origin_margin = 0.0f;                      // IvgParams::origin_margin
    size_t empty_cells = 0;                          // no triangle overlaps them
    size_t unsupported_cells = 0;  // no plane of theirs leaves a side free, or left unclassified
    size_t copied_triangles = 0;   // left out: an earlier triangle has the same vertices
    size_t skipped_triangles = 0;  // left out: over the budget; their cells unclassified
    size_t box_tests = 0;          // triangle-box tests made
};

// Triangle-box tests per distinct triangle and per cell the classification may make in all.
constexpr size_t kIvgBoxTestsPerElement = 256;

// The cells of the grid `params` places, classified against `mesh` (the scene posed at the grid's
// frame; the triangles the BVH holds). Deterministic: a cell's planes are tried in the order of
// its triangles in the mesh. Tests may pass a budget of their own.
IvgCellPlanes classify_cell_planes(const TriangleMesh& mesh, const shared::IvgParams& params,
                                   size_t box_tests_per_element = kIvgBoxTestsPerElement);

}  // namespace rc
