#include "methods/caching/record_grid.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

#include "methods/caching/record_store.h"
#include "util/error.h"
#include "util/glm_helpers.h"

namespace rc {
namespace {

// The cells a record's influence sphere's bounding box touches, [from, to] inclusive.
struct CellRange {
    glm::ivec3 from;
    glm::ivec3 to;
};

// The cells a record listed over [lower, ...) with cells of `cell` touches (not clamped to the
// grid: an upper bound).
double listings_for(const std::vector<shared::Record>& records, const std::vector<float>& influence,
                    glm::vec3 lower, float cell) {
    double listings = 0.0;
    for (size_t i = 0; i < records.size(); ++i) {
        const glm::vec3 p = record_position(records[i]);
        const glm::vec3 span = glm::floor((p + influence[i] - lower) / cell) -
                               glm::floor((p - influence[i] - lower) / cell) + 1.0f;
        listings += static_cast<double>(span.x) * span.y * span.z;
    }
    return listings;
}

// The cell size: about cell_per_radius times the median influence radius, grown by 1.25 while there
// would be more than max_cells cells or more than kMaxListingsPerRecord listings per record on
// average. (A cache's radii span decades: with cells from the median alone, the large records of a
// deeper level were each listed in hundreds of cells — 8 M listings for 12 k records on the Cornell
// box — and building the grid was most of the host's work in a render. Once cells exceed the extent
// a record touches at most 8, so the growth ends.)
float cell_size(const std::vector<shared::Record>& records, const std::vector<float>& influence,
                glm::vec3 lower, glm::vec3 extent, size_t max_cells, float cell_per_radius) {
    std::vector<float> sorted = influence;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    float cell = std::max({cell_per_radius * sorted[sorted.size() / 2], 1e-6f * glm::length(extent),
                           std::numeric_limits<float>::min()});
    auto cells_for = [&](float size) {
        const glm::vec3 dims = glm::ceil(extent / size);
        return static_cast<double>(dims.x) * dims.y * dims.z;
    };
    const double max_listings = kMaxListingsPerRecord * static_cast<double>(records.size());
    while (cells_for(cell) > static_cast<double>(max_cells) ||
           listings_for(records, influence, lower, cell) > max_listings) {
        cell *= 1.25f;
    }
    return cell;
}

}  // namespace

RecordGridData build_record_grid(const std::vector<shared::Record>& records, float accuracy,
                                 size_t max_cells, float cell_per_radius) {
    RecordGridData data;
    if (records.empty()) {
        data.grid.origin = {0, 0, 0, 0};
        data.grid.inv_cell = {1, 1, 1, 0};
        data.grid.dims = {1, 1, 1, 1};
        data.cell_start = {0, 0};
        return data;
    }
    // 1. Bounds of every influence sphere and the cell size.
    glm::vec3 lower(std::numeric_limits<float>::max());
    glm::vec3 upper(-std::numeric_limits<float>::max());
    std::vector<float> influence(records.size());
    for (size_t i = 0; i < records.size(); ++i) {
        influence[i] = accuracy * records[i].radius;
        lower = glm::min(lower, record_position(records[i]) - glm::vec3(influence[i]));
        upper = glm::max(upper, record_position(records[i]) + glm::vec3(influence[i]));
    }
    // A flat or single-point set still gets a thickness: a millionth of its largest span, not an
    // absolute length (with 1e-6, a scene scaled by 1e-11 had a grid far larger than itself, its
    // few cells listing thousands of records each: the decomposition's near-field gather over
    // 115 k split triangles took 16 times as long at 5e-11 and did not finish at 3e-11).
    const glm::vec3 span = upper - lower;
    const float thickness =
        std::max(1e-6f * std::max({span.x, span.y, span.z}), std::numeric_limits<float>::min());
    const glm::vec3 extent = glm::max(span, glm::vec3(thickness));
    const float cell = cell_size(records, influence, lower, extent, max_cells, cell_per_radius);
    const glm::ivec3 dims = glm::max(glm::ivec3(glm::ceil(extent / cell)), glm::ivec3(1));
    const size_t cells = static_cast<size_t>(dims.x) * dims.y * dims.z;
    data.grid.origin = float4_of(lower);
    data.grid.inv_cell = float4_of(glm::vec3(1.0f / cell));
    data.grid.dims = {dims.x, dims.y, dims.z, static_cast<int>(cells)};

    // 2. Counting sort of (cell, record) pairs; records ascend within each cell.
    auto cell_range = [&](size_t i) {
        const glm::vec3 p = record_position(records[i]);
        return CellRange{
            glm::clamp(glm::ivec3((p - influence[i] - lower) / cell), glm::ivec3(0), dims - 1),
            glm::clamp(glm::ivec3((p + influence[i] - lower) / cell), glm::ivec3(0), dims - 1)};
    };
    auto for_each_cell = [&](size_t i, auto&& visit) {
        const CellRange r = cell_range(i);
        for (int z = r.from.z; z <= r.to.z; ++z) {
            for (int y = r.from.y; y <= r.to.y; ++y) {
                for (int x = r.from.x; x <= r.to.x; ++x) {
                    visit((static_cast<size_t>(z) * dims.y + y) * dims.x + x);
                }
            }
        }
    };
    std::vector<int> counts(cells + 1, 0);
    for (size_t i = 0; i < records.size(); ++i) {
        for_each_cell(i, [&](size_t c) { ++counts[c + 1]; });
    }
    for (size_t c = 0; c < cells; ++c) {
        counts[c + 1] += counts[c];
    }
    if (counts[cells] > std::numeric_limits<int>::max() / 2) {
        throw Error("record grid: too many record references");
    }
    data.cell_start = counts;
    data.cell_records.assign(static_cast<size_t>(counts[cells]), 0);
    std::vector<int> fill(counts.begin(), counts.end() - 1);
    for (size_t i = 0; i < records.size(); ++i) {
        for_each_cell(i, [&](size_t c) { data.cell_records[fill[c]++] = static_cast<int>(i); });
    }
    return data;
}

}  // namespace rc
