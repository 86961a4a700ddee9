// The record grid (host/methods/caching/record_grid.cpp) against brute force over its cells:
// every record is listed, once and in ascending order, in every cell its influence sphere
// touches.
#include "methods/caching/record_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <random>

#include "methods/caching/record_store.h"

namespace rc {
namespace {

// Records at random places with radii spanning two decades.
std::vector<shared::Record> random_records(std::mt19937& rng, int count) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<shared::Record> records;
    for (int i = 0; i < count; ++i) {
        shared::Record r = make_record(glm::vec3(10.0f * unit(rng), 4.0f * unit(rng), unit(rng)),
                                       glm::vec3(0.0f, 1.0f, 0.0f));
        r.radius = std::pow(10.0f, -1.5f + 2.0f * unit(rng));
        records.push_back(r);
    }
    return records;
}

// Distance from p to the box [lower, upper].
float box_distance(glm::vec3 p, glm::vec3 lower, glm::vec3 upper) {
    return glm::length(glm::max(glm::max(lower - p, p - upper), glm::vec3(0.0f)));
}

void expect_lists_every_touching_record(const std::vector<shared::Record>& records, float accuracy,
                                        size_t max_cells) {
    const RecordGridData data = build_record_grid(records, accuracy, max_cells);
    const shared::RecordGrid& g = data.grid;
    const size_t cells = static_cast<size_t>(g.dims.x) * g.dims.y * g.dims.z;
    ASSERT_EQ(static_cast<size_t>(g.dims.w), cells);
    ASSERT_LE(cells, max_cells);
    ASSERT_EQ(data.cell_start.size(), cells + 1);
    ASSERT_EQ(static_cast<size_t>(data.cell_start.back()), data.cell_records.size());
    const glm::vec3 origin(g.origin.x, g.origin.y, g.origin.z);
    const glm::vec3 size = 1.0f / glm::vec3(g.inv_cell.x, g.inv_cell.y, g.inv_cell.z);
    size_t listings = 0;
    for (int z = 0; z < g.dims.z; ++z) {
        for (int y = 0; y < g.dims.y; ++y) {
            for (int x = 0; x < g.dims.x; ++x) {
                const size_t c = (static_cast<size_t>(z) * g.dims.y + y) * g.dims.x + x;
                const auto first = data.cell_records.begin() + data.cell_start[c];
                const auto last = data.cell_records.begin() + data.cell_start[c + 1];
                ASSERT_TRUE(std::is_sorted(first, last));
                ASSERT_EQ(std::adjacent_find(first, last), last) << "a record twice in a cell";
                const glm::vec3 lower = origin + glm::vec3(x, y, z) * size;
                for (size_t i = 0; i < records.size(); ++i) {
                    // Touching by a margin, so rounding of the cell size cannot decide it.
                    const float influence = accuracy * records[i].radius;
                    if (box_distance(record_position(records[i]), lower, lower + size) <
                        influence - 1e-4f * size.x) {
                        ++listings;
                        ASSERT_TRUE(std::binary_search(first, last, static_cast<int>(i)))
                            << "record " << i << " missing from cell (" << x << ", " << y << ", "
                            << z << ")";
                    }
                }
            }
        }
    }
    EXPECT_GT(listings, records.size());
}

TEST(RecordGrid, ListsEveryRecordInEveryCellItsInfluenceTouches) {
    std::mt19937 rng(5);
    expect_lists_every_touching_record(random_records(rng, 300), 0.4f, size_t{1} << 21);
}

// With few cells allowed the cells grow and a record spans many of them.
TEST(RecordGrid, ListsEveryRecordWhenCellsAreCapped) {
    std::mt19937 rng(7);
    expect_lists_every_touching_record(random_records(rng, 200), 0.9f, 64);
}

// A cache's radii span decades: a few large records among many small ones must not be listed in
// the thousands of small cells the median radius alone would make.
TEST(RecordGrid, ListingsPerRecordStayBoundedWhenRadiiSpanDecades) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<shared::Record> records;
    for (int i = 0; i < 400; ++i) {
        shared::Record r = make_record(glm::vec3(10.0f * unit(rng), 4.0f * unit(rng), unit(rng)),
                                       glm::vec3(0.0f, 0.0f, 1.0f));
        r.radius = i % 20 == 0 ? 3.0f + unit(rng) : 0.01f + 0.01f * unit(rng);
        records.push_back(r);
    }
    const size_t max_cells = size_t{1} << 16;
    const RecordGridData data = build_record_grid(records, 1.0f, max_cells);
    // 64 per record (kMaxListingsPerRecord); the median radius alone gives 400 times more.
    EXPECT_LE(data.cell_records.size(), 64 * records.size());
    expect_lists_every_touching_record(records, 1.0f, max_cells);
}

TEST(RecordGrid, EmptyGridHasOneEmptyCell) {
    const RecordGridData data = build_record_grid({}, 0.5f);
    EXPECT_EQ(data.grid.dims.w, 1);
    EXPECT_EQ(data.cell_start, (std::vector<int>{0, 0}));
    EXPECT_TRUE(data.cell_records.empty());
}

}  // namespace
}  // namespace rc
