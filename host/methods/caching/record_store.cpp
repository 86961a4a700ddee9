#include "methods/caching/record_store.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <string>

#include "util/parallel_ranges.h"

namespace rc {

glm::vec3 record_position(const shared::Record& record) {
    return {record.position.x, record.position.y, record.position.z};
}

glm::vec3 record_normal(const shared::Record& record) {
    return {record.normal.x, record.normal.y, record.normal.z};
}

shared::Record make_record(glm::vec3 p, glm::vec3 n) {
    shared::Record record{};
    record.position = {p.x, p.y, p.z, 0.0f};
    record.normal = {n.x, n.y, n.z, 0.0f};
    return record;
}

RecordStore::RecordStore(float accuracy, size_t payload_bytes)
    : accuracy_(accuracy), payload_bytes_(payload_bytes) {}

void RecordStore::check_payload_size(size_t bytes) const {
    if (bytes != payload_bytes_) {
        throw Error("record store: a payload of " + std::to_string(bytes) +
                    " bytes in a store of " + std::to_string(payload_bytes_) + "-byte payloads");
    }
}

void RecordStore::set_radius(size_t i, float radius) {
    host_[i].radius = radius;
    records_[i].radius = std::clamp(radius, host_[i].r_min, host_[i].r_max);
}

float RecordStore::gradient_scale(size_t i) const {
    const float radius = host_[i].radius;
    const float clamped = records_[i].radius;
    return radius < clamped ? radius / clamped : 1.0f;
}

namespace {

// The radius class of R: the smallest L with R <= 2^L.
int radius_class(float radius) {
    if (!(radius > 0.0f)) {
        return -126;
    }
    if (!std::isfinite(radius)) {
        return 127;
    }
    int exponent = 0;
    const float mantissa = std::frexp(radius, &exponent);  // radius = mantissa 2^exponent
    return mantissa == 0.5f ? exponent - 1 : exponent;
}

glm::ivec3 cell_of(glm::vec3 p, float cell) {
    const glm::vec3 c =
        glm::clamp(glm::floor(p / cell), glm::vec3(-1048576.0f), glm::vec3(1048575.0f));
    return glm::ivec3(c);
}

uint64_t cell_key(glm::ivec3 c) {
    return (static_cast<uint64_t>(static_cast<uint32_t>(c.x) & 0x1fffffu) << 42) |
           (static_cast<uint64_t>(static_cast<uint32_t>(c.y) & 0x1fffffu) << 21) |
           static_cast<uint64_t>(static_cast<uint32_t>(c.z) & 0x1fffffu);
}

}  // namespace

float RecordStore::grid_cell(int level, int grid) {
    return std::ldexp(1.0f, level + kGridOffset + grid);
}

template <class ReachOf, class Visit>
void RecordStore::visit_within(glm::vec3 p, ReachOf&& reach_of, Visit&& visit) const {
    for (const auto& [level, radius_class] : classes_) {
        // Class members have R_k <= 2^level; the caller gives how far from p a member can matter
        // at that bound (nothing at a reach <= 0). The grid taken: the coarsest whose cells are
        // at most kCellPerReach reaches (or the finest). Entries of records that have since moved
        // to a smaller class are skipped.
        const float reach = reach_of(std::ldexp(1.0f, level));
        if (!(reach > 0.0f)) {
            continue;
        }
        int grid = 0;
        while (grid + 1 < kGrids && grid_cell(level, grid + 1) <= kCellPerReach * reach) {
            ++grid;
        }
        const float cell = grid_cell(level, grid);
        const glm::ivec3 from = cell_of(p - glm::vec3(reach), cell);
        const glm::ivec3 to = cell_of(p + glm::vec3(reach), cell);
        const glm::dvec3 span = glm::dvec3(to - from) + 1.0;
        if (!std::isfinite(reach) || span.x * span.y * span.z > radius_class.records.size()) {
            for (uint32_t k : radius_class.records) {
                if (class_of_[k] == level) {
                    visit(k);
                }
            }
            continue;
        }
        const auto& cells = radius_class.cells[grid];
        for (int z = from.z; z <= to.z; ++z) {
            for (int y = from.y; y <= to.y; ++y) {
                for (int x = from.x; x <= to.x; ++x) {
                    const auto it = cells.find(cell_key({x, y, z}));
                    if (it != cells.end()) {
                        for (uint32_t k : it->second) {
                            if (class_of_[k] == level) {
                                visit(k);
                            }
                        }
                    }
                }
            }
        }
    }
}

size_t RecordStore::insert_bytes(const shared::Record& record, const RecordHostData& host,
                                 const void* payload, size_t bytes, float radius_limit) {
    check_payload_size(bytes);
    return insert_batch({{record, host, payload, radius_limit}});
}

unsigned RecordStore::threads() const { return threads_ > 0 ? threads_ : host_threads(); }

size_t RecordStore::insert_batch(const std::vector<NewRecord>& batch) {
    // R from the harmonic mean distance (infinite where no ray hit), limited by the method's
    // limit (irradiance caching: the translational gradient, course "Gradient Limit on Record
    // Spacing"). Neighbor clamping works on this unclamped R; the [r_min, r_max] clamp comes after
    // it (course, "Summary of Implementation Details": "it is essential to use the original,
    // unclamped value of R").
    const size_t first = records_.size();
    std::vector<uint32_t> added;
    added.reserve(batch.size());
    for (const NewRecord& r : batch) {
        const size_t j = records_.size();
        records_.push_back(r.record);
        host_.push_back(r.host);
        const std::byte* data = static_cast<const std::byte*>(r.payload);
        payloads_.insert(payloads_.end(), data, data + payload_bytes_);
        set_radius(j, std::min(r.host.harmonic_distance, r.radius_limit));
        index_record(static_cast<uint32_t>(j));
        added.push_back(static_cast<uint32_t>(j));
    }
    // Neighbor clamping (R_b <= R_a + |p_a - p_b| for every pair) to its greatest fixed point
    // below the initial radii: the store held it before the batch, so a pair breaks it only
    // through a new record. First each new record is lowered by every record near it (their
    // radii as they stand), then rounds of pushes from every record whose R was last set, until
    // none lowers another. Each round reads the radii of the round before (the bounds are
    // collected before any is applied) and takes the least bound per record, and float addition
    // is monotone, so every order, split over threads or not, ends at the same fixed point, bit
    // for bit (tests/caching/record_store_test.cpp checks it against brute force over every pair).
    lower(pulled_bounds(added));
    std::vector<uint32_t> changed = std::move(added);
    while (!changed.empty()) {
        changed = lower(pushed_bounds(changed));
    }
    return first;
}

template <class BoundsOf>
std::vector<RecordStore::Bound> RecordStore::collect_bounds(const std::vector<uint32_t>& indices,
                                                            BoundsOf&& bounds_of) const {
    // Below a few dozen searches a thread costs more than it saves.
    constexpr size_t kSearchesPerThread = 32;
    const unsigned parts = static_cast<unsigned>(std::min<size_t>(
        threads(), (indices.size() + kSearchesPerThread - 1) / kSearchesPerThread));
    std::vector<std::vector<Bound>> part_bounds(std::max(1u, parts));
    // Handed out a few at a time: a large record's search costs thousands of a small one's. The
    // bounds' order does not matter (lower() takes the least per record).
    parallel_items(indices.size(), parts, 8,
                   [&](size_t i, size_t part) { bounds_of(indices[i], part_bounds[part]); });
    std::vector<Bound> bounds;
    for (const std::vector<Bound>& part : part_bounds) {
        bounds.insert(bounds.end(), part.begin(), part.end());
    }
    return bounds;
}

std::vector<RecordStore::Bound> RecordStore::pulled_bounds(
    const std::vector<uint32_t>& added) const {
    // Record k lowers R_j when R_k + d < R_j, so only records within d < R_j are visited.
    return collect_bounds(added, [this](uint32_t j, std::vector<Bound>& out) {
        const glm::vec3 p = record_position(records_[j]);
        const float radius_j = host_[j].radius;
        float radius = radius_j;
        visit_within(
            p, [radius_j](float) { return radius_j; },
            [&](uint32_t k) {
                const float d = glm::length(p - record_position(records_[k]));
                if (k != j && d < radius_j + host_[k].radius) {
                    radius = std::min(radius, host_[k].radius + d);
                }
            });
        if (radius < radius_j) {
            out.push_back({j, radius});
        }
    });
}

std::vector<RecordStore::Bound> RecordStore::pushed_bounds(
    const std::vector<uint32_t>& changed) const {
    // Record a lowers R_b when R_a + d < R_b <= 2^L (b of class L), so d < 2^L - R_a, and classes
    // with 2^L <= R_a are skipped. Most overlapping pairs do not qualify (large deeper-level
    // records overlap thousands).
    return collect_bounds(changed, [this](uint32_t a, std::vector<Bound>& out) {
        const glm::vec3 pa = record_position(records_[a]);
        const float radius_a = host_[a].radius;
        visit_within(
            pa, [radius_a](float bound) { return bound - radius_a; },
            [&](uint32_t b) {
                const float bound = radius_a + glm::length(pa - record_position(records_[b]));
                if (b != a && bound < host_[b].radius) {
                    out.push_back({b, bound});
                }
            });
    });
}

std::vector<uint32_t> RecordStore::lower(const std::vector<Bound>& bounds) {
    least_bound_.resize(records_.size(), std::numeric_limits<float>::infinity());
    std::vector<uint32_t> lowered;
    for (const Bound& bound : bounds) {
        float& least = least_bound_[bound.index];
        if (least == std::numeric_limits<float>::infinity()) {  // its first bound
            lowered.push_back(bound.index);
        }
        least = std::min(least, bound.radius);
    }
    std::sort(lowered.begin(), lowered.end());
    for (uint32_t index : lowered) {
        set_radius(index, least_bound_[index]);
        least_bound_[index] = std::numeric_limits<float>::infinity();
        index_record(index);
    }
    return lowered;
}

void RecordStore::index_record(uint32_t index) {
    // R only shrinks after insertion: a record whose R fell into a smaller class is listed there
    // too, and its entries in the larger class are skipped from then on (class_of_), so each
    // class bounds its members' R within a factor of 2.
    const int level = radius_class(host_[index].radius);
    if (index < class_of_.size() && class_of_[index] == level) {
        return;
    }
    class_of_.resize(std::max(class_of_.size(), size_t{index} + 1));
    class_of_[index] = level;
    RadiusClass& radius_class = classes_[level];
    radius_class.records.push_back(index);
    const glm::vec3 p = record_position(records_[index]);
    for (int grid = 0; grid < kGrids; ++grid) {
        radius_class.cells[grid][cell_key(cell_of(p, grid_cell(level, grid)))].push_back(index);
    }
}

void RecordStore::restore(std::vector<shared::Record> records, std::vector<RecordHostData> host,
                          std::vector<std::byte> payloads) {
    if (host.size() != records.size() || payloads.size() != records.size() * payload_bytes_) {
        throw Error("record store: " + std::to_string(records.size()) + " records with " +
                    std::to_string(host.size()) + " host entries and " +
                    std::to_string(payloads.size()) + " payload bytes");
    }
    records_ = std::move(records);
    host_ = std::move(host);
    payloads_ = std::move(payloads);
    classes_.clear();
    class_of_.clear();
    for (uint32_t i = 0; i < records_.size(); ++i) {
        set_radius(i, host_[i].radius);
        index_record(i);
    }
}

}  // namespace rc
