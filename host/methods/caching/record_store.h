// The record store every caching method shares (DESIGN.md §2, §6.2 step 4): records inserted in
// record-index order with their validity radius R limited by the harmonic mean distance and by a
// limit the method supplies; neighbor clamping on that unclamped R; then the [R_min, R_max]
// clamp, with the
// factor a method scales its payload's gradients by when the clamp raised R. A record is its
// shared part (shared::Record, kernels/shared/records.h), the host-only data below and the
// method's payload, stored once, as bytes the store never interprets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <glm/vec3.hpp>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "shared/records.h"
#include "util/error.h"

namespace rc {

// What the host keeps about a record beside its shared part and payload.
struct RecordHostData {
    float harmonic_distance = 0.0f;  // of the record's hemisphere hits (infinite: none)
    float min_distance = 0.0f;
    float r_min = 0.0f;  // bounds on the validity radius R, from the footprint where it was made
    float r_max = 0.0f;
    // R before the [r_min, r_max] clamp: the harmonic mean distance (infinite: no hit) limited by
    // the method's limit, then by neighbor clamping (set by RecordStore::insert).
    float radius = 0.0f;
};
static_assert(sizeof(RecordHostData) == 20);

glm::vec3 record_position(const shared::Record& record);
glm::vec3 record_normal(const shared::Record& record);
// A record's shared part at p with normal n, radius 0 (set on insertion).
shared::Record make_record(glm::vec3 p, glm::vec3 n);

// A record to insert: its shared part, host data, payload (the store's payload_bytes()) and the
// method's limit on its validity radius.
struct NewRecord {
    shared::Record record;
    RecordHostData host;
    const void* payload = nullptr;
    float radius_limit = 0.0f;
};

class RecordStore {
   public:
    // `accuracy` a: a record influences points within a R. Every payload has `payload_bytes`.
    RecordStore(float accuracy, size_t payload_bytes);

    // Adds a record: R = min(harmonic distance (infinite: no hit), radius_limit), then
    // neighbor clamping (course "Neighbor Clamping", "Summary of Implementation Details") with
    // every record whose sphere of radius R overlaps: R_j = min(R_j, R_k + |p_j - p_k|), then
    // R_k = min(R_k, R_j + |p_j - p_k|), propagated until every overlapping pair satisfies the
    // triangle inequality. The shared part's radius is kept at clamp(R, r_min, r_max). Returns
    // the new record's index.
    template <class Payload>
    size_t insert(const shared::Record& record, const RecordHostData& host, const Payload& payload,
                  float radius_limit) {
        static_assert(std::is_trivially_copyable_v<Payload>);
        return insert_bytes(record, host, &payload, sizeof(Payload), radius_limit);
    }
    // The same for a payload whose size is chosen at run time: `bytes` must be payload_bytes().
    size_t insert_bytes(const shared::Record& record, const RecordHostData& host,
                        const void* payload, size_t bytes, float radius_limit);
    // Adds records in one batch, numbered in order: the radii are those of inserting them one by
    // one, bit for bit (neighbor clamping's greatest fixed point does not depend on the order),
    // with the neighbor searches spread over threads(). Returns the first one's index.
    size_t insert_batch(const std::vector<NewRecord>& batch);
    // Host threads for the neighbor searches (0: host_threads()); any count, the same radii.
    void set_threads(unsigned threads) { threads_ = threads; }
    unsigned threads() const;

    // Restores records as they were stored (host.radius already final), for cache files.
    void restore(std::vector<shared::Record> records, std::vector<RecordHostData> host,
                 std::vector<std::byte> payloads);

    // The shared parts, radius clamped to [r_min, r_max]: what the kernels read.
    const std::vector<shared::Record>& records() const { return records_; }
    const std::vector<RecordHostData>& host_data() const { return host_; }
    // Every payload, record by record, payload_bytes() each.
    const std::vector<std::byte>& payloads() const { return payloads_; }
    const std::byte* payload_data(size_t i) const { return payloads_.data() + i * payload_bytes_; }
    template <class Payload>
    Payload payload(size_t i) const {
        static_assert(std::is_trivially_copyable_v<Payload>);
        check_payload_size(sizeof(Payload));
        Payload p;
        std::memcpy(&p, payload_data(i), sizeof p);
        return p;
    }
    // R / R' when the [r_min, r_max] clamp raised R to R', else 1: the method scales its
    // payload's gradients by it so extrapolation to the larger border stays as bounded as at R.
    float gradient_scale(size_t i) const;

    size_t size() const { return records_.size(); }
    float accuracy() const { return accuracy_; }
    size_t payload_bytes() const { return payload_bytes_; }

   private:
    // Records hashed by position, a pyramid of grids per radius class: the records of class L
    // have R <= 2^L and sit in cells of size grid_cell(L, g) of grid g. A query takes the
    // coarsest grid whose cells are at most kCellPerReach times its reach: a few cells to look
    // up whatever its radius (hash lookups, not distance tests, were the cost of insertion).
    static constexpr int kGrids = 6;
    static constexpr int kGridOffset = 2;
    static constexpr float kCellPerReach = 4.0f;
    // The cell size of grid g of class L: 2^(L + kGridOffset + g).
    static float grid_cell(int level, int grid);
    struct RadiusClass {
        std::vector<uint32_t> records;
        std::unordered_map<uint64_t, std::vector<uint32_t>> cells[kGrids];
    };
    void check_payload_size(size_t bytes) const;
    // Sets the unclamped R of record i and its shared part's clamped radius.
    void set_radius(size_t i, float radius);
    // Calls visit(k) for every record k of every radius class L with |p - p_k| <
    // reach_of(2^L), and maybe a few more (each once; in no particular order: neighbor
    // clamping's result does not depend on it). A reach <= 0 skips the class.
    template <class ReachOf, class Visit>
    void visit_within(glm::vec3 p, ReachOf&& reach_of, Visit&& visit) const;
    void index_record(uint32_t index);
    // A lower bound proposed for record `index`'s unclamped R.
    struct Bound {
        uint32_t index;
        float radius;
    };
    // Neighbor clamping's pull: for each record of `added`, the least R_k + |p_j - p_k| over the
    // records k that overlap it, where lower than its R.
    std::vector<Bound> pulled_bounds(const std::vector<uint32_t>& added) const;
    // Its push: for each record a of `changed`, R_a + |p_a - p_b| for every record b it lowers.
    std::vector<Bound> pushed_bounds(const std::vector<uint32_t>& changed) const;
    // Applies the least bound per record; returns the records lowered, in index order.
    std::vector<uint32_t> lower(const std::vector<Bound>& bounds);
    // Calls bounds_of(i, out) for every i of `indices` over threads(), output in indices' order.
    template <class BoundsOf>
    std::vector<Bound> collect_bounds(const std::vector<uint32_t>& indices,
                                      BoundsOf&& bounds_of) const;

    float accuracy_;
    size_t payload_bytes_;
    std::vector<shared::Record> records_;
    std::vector<RecordHostData> host_;
    std::vector<std::byte> payloads_;
    std::unordered_map<int, RadiusClass> classes_;
    std::vector<int> class_of_;  // the class each record is listed in (its smallest so far)
    unsigned threads_ = 0;
    std::vector<float> least_bound_;  // lower()'s scratch: +inf but where a bound was proposed
};

}  // namespace rc
