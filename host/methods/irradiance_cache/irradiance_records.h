// The irradiance cache's records on the host (DESIGN.md §6.2 step 4): insertion in record-index
// order with the radius limited by the gradient, neighbor clamping, clamping to [R_min, R_max]
// with the gradients scaled down when R was raised, and the world-space grid the kernels query.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

#include "shared/types.h"

namespace rc {

// A record as computed by the record kernels, with the bounds its pixel footprint gives.
struct CacheRecord {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec3 irradiance{0.0f};
    glm::vec3 rotation[3] = {};     // rotational gradient per RGB channel
    glm::vec3 translation[3] = {};  // translational gradient per RGB channel
    float harmonic_distance = 0.0f;
    float min_distance = 0.0f;
    glm::vec3 occluder{0.0f};  // tangent-plane offset of the nearest hit (rc_ic_weight)
    float r_min = 0.0f;        // bounds on the validity radius R
    float r_max = 0.0f;
    // R before the [r_min, r_max] clamp: the harmonic mean distance limited by the gradient and
    // by r_max, then by neighbor clamping (set by RecordStore::insert).
    float radius = 0.0f;
};

// Every record's device form and the grid over their influence spheres.
struct RecordGridData {
    shared::RecordGrid grid{};
    std::vector<int> cell_start;    // cells + 1 entries
    std::vector<int> cell_records;  // record indices, cell by cell, ascending within a cell
};

class RecordStore {
   public:
    // `accuracy` a: a record influences points within a * R.
    explicit RecordStore(float accuracy) : accuracy_(accuracy) {}

    // Adds a record: R = min(harmonic distance, E / |grad_t E| (luminance), r_max), then
    // neighbor clamping (course "Neighbor Clamping", "Summary of Implementation Details") with
    // every record whose sphere of radius R overlaps: R_j = min(R_j, R_k + |p_j - p_k|), then
    // R_k = min(R_k, R_j + |p_j - p_k|), propagated until every overlapping pair satisfies the
    // triangle inequality. Returns the new record's index.
    size_t insert(CacheRecord record);

    const std::vector<CacheRecord>& records() const { return records_; }
    size_t size() const { return records_.size(); }
    float accuracy() const { return accuracy_; }

    // The kernels' form of record i: R' = clamp(R, r_min, r_max), gradients scaled by R / R'
    // when the clamp raised R.
    shared::IrradianceRecord device_record(size_t i) const;
    std::vector<shared::IrradianceRecord> device_records() const;

    // A uniform grid over the records' influence spheres (radius a R'), each record listed in
    // every cell its sphere's bounding box touches; cells are sized from the median influence
    // radius, at most `max_cells` in all.
    RecordGridData build_grid(size_t max_cells = size_t{1} << 21) const;

    // Restores records as they were stored (radius already final), for cache files.
    void restore(std::vector<CacheRecord> records);

   private:
    // Records hashed by position, one grid per radius class: the records of class L have
    // R <= 2^L and sit in cells of size 2^L.
    struct RadiusClass {
        std::vector<uint32_t> records;
        std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
    };
    // Indices of every record k with |p - p_k| < radius + R_k, and maybe a few more.
    std::vector<uint32_t> overlapping(glm::vec3 p, float radius) const;
    void index_record(uint32_t index);

    float accuracy_;
    std::vector<CacheRecord> records_;
    std::unordered_map<int, RadiusClass> classes_;
};

}  // namespace rc
