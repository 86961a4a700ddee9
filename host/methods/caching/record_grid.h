// The world-space uniform grid over records' influence spheres that the kernels query
// (DESIGN.md §6.2 steps 4 and 6): each record is listed in every cell its influence sphere's
// bounding box touches, in ascending record order within a cell.
#pragma once

#include <cstddef>
#include <vector>

#include "shared/records.h"

namespace rc {

// The grid and its cell lists as the kernels read them.
struct RecordGridData {
    shared::RecordGrid grid{};
    std::vector<int> cell_start;    // cells + 1 entries
    std::vector<int> cell_records;  // record indices, cell by cell, ascending within a cell
};

// The most listings per record the grid makes on average (record_grid.cpp, cell_size).
constexpr double kMaxListingsPerRecord = 64.0;

// The grid over spheres of radius accuracy * R' (R' = records[i].radius) around the records;
// cells are `cell_per_radius` times the median influence radius (larger where needed), at most
// `max_cells` in all and at most kMaxListingsPerRecord listings per record on average. Smaller
// cells list a record in more cells and give a query fewer records that cannot reach it.
RecordGridData build_record_grid(const std::vector<shared::Record>& records, float accuracy,
                                 size_t max_cells = size_t{1} << 21, float cell_per_radius = 2.0f);

}  // namespace rc
