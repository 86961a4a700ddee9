#include "methods/irradiance_cache/irradiance_records.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "util/error.h"

namespace rc {
namespace {

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

shared::float4 float4_of(glm::vec3 v, float w = 0.0f) { return {v.x, v.y, v.z, w}; }

float clamped_radius(const CacheRecord& r) { return std::clamp(r.radius, r.r_min, r.r_max); }

}  // namespace

size_t RecordStore::insert(CacheRecord record) {
    // R from the harmonic mean distance, limited by the translational gradient: |grad E| R <= E
    // keeps first-order extrapolation within the radius non-negative (course, "Gradient Limit on
    // Record Spacing"), and by r_max, above which R never matters (this keeps neighbor searches
    // local; the lower clamp comes only after neighbor clamping).
    float radius =
        std::isfinite(record.harmonic_distance) ? record.harmonic_distance : record.r_max;
    const glm::vec3 gradient = 0.2126f * record.translation[0] + 0.7152f * record.translation[1] +
                               0.0722f * record.translation[2];
    const float e = luminance(record.irradiance);
    const float g = glm::length(gradient);
    if (g > 0.0f && e > 0.0f) {
        radius = std::min(radius, e / g);
    }
    record.radius = std::min(radius, record.r_max);

    // Neighbor clamping: first the new record by every record it overlaps, then the others by it,
    // and on from every record that changed. (The course clamps one ring of neighbors; the
    // relaxation only goes further if a neighbor's R had been loaded from elsewhere. The result,
    // R_j <= R_k + |p_j - p_k| for every pair, does not depend on the visiting order: a record
    // that lowers R_j always overlaps it.)
    for (uint32_t k : overlapping(record.position, record.radius)) {
        const CacheRecord& other = records_[k];
        const float d = glm::length(record.position - other.position);
        if (d < record.radius + other.radius) {
            record.radius = std::min(record.radius, other.radius + d);
        }
    }
    const size_t j = records_.size();
    records_.push_back(record);
    index_record(static_cast<uint32_t>(j));
    std::vector<size_t> changed = {j};
    while (!changed.empty()) {
        const size_t a = changed.back();
        changed.pop_back();
        for (uint32_t b : overlapping(records_[a].position, records_[a].radius)) {
            if (b == a) {
                continue;
            }
            const float d = glm::length(records_[a].position - records_[b].position);
            if (d < records_[a].radius + records_[b].radius &&
                records_[b].radius > records_[a].radius + d) {
                records_[b].radius = records_[a].radius + d;
                changed.push_back(b);
            }
        }
    }
    return j;
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

std::vector<uint32_t> RecordStore::overlapping(glm::vec3 p, float radius) const {
    std::vector<uint32_t> found;
    for (const auto& [level, radius_class] : classes_) {
        // Class members have R_k <= cell, so overlapping ones lie within radius + cell of p.
        const float cell = std::ldexp(1.0f, level);
        const float reach = radius + cell;
        const glm::ivec3 from = cell_of(p - glm::vec3(reach), cell);
        const glm::ivec3 to = cell_of(p + glm::vec3(reach), cell);
        const glm::dvec3 span = glm::dvec3(to - from) + 1.0;
        if (!std::isfinite(reach) || span.x * span.y * span.z > radius_class.records.size()) {
            found.insert(found.end(), radius_class.records.begin(), radius_class.records.end());
            continue;
        }
        for (int z = from.z; z <= to.z; ++z) {
            for (int y = from.y; y <= to.y; ++y) {
                for (int x = from.x; x <= to.x; ++x) {
                    const auto it = radius_class.cells.find(cell_key({x, y, z}));
                    if (it != radius_class.cells.end()) {
                        found.insert(found.end(), it->second.begin(), it->second.end());
                    }
                }
            }
        }
    }
    return found;
}

void RecordStore::index_record(uint32_t index) {
    // R only shrinks after insertion, so the class chosen now stays an upper bound.
    const int level = radius_class(records_[index].radius);
    RadiusClass& radius_class = classes_[level];
    radius_class.records.push_back(index);
    radius_class.cells[cell_key(cell_of(records_[index].position, std::ldexp(1.0f, level)))]
        .push_back(index);
}

shared::IrradianceRecord RecordStore::device_record(size_t i) const {
    const CacheRecord& r = records_[i];
    const float clamped = clamped_radius(r);
    // When the clamp raised R, scale the gradients down so extrapolation over the larger radius
    // stays as bounded as over R.
    const float scale = r.radius < clamped ? r.radius / clamped : 1.0f;
    shared::IrradianceRecord d{};
    d.position = float4_of(r.position, clamped);
    d.normal = float4_of(r.normal);
    d.irradiance = float4_of(r.irradiance);
    d.rotation_r = float4_of(scale * r.rotation[0]);
    d.rotation_g = float4_of(scale * r.rotation[1]);
    d.rotation_b = float4_of(scale * r.rotation[2]);
    d.translation_r = float4_of(scale * r.translation[0]);
    d.translation_g = float4_of(scale * r.translation[1]);
    d.translation_b = float4_of(scale * r.translation[2]);
    d.occluder = float4_of(r.occluder);
    return d;
}

std::vector<shared::IrradianceRecord> RecordStore::device_records() const {
    std::vector<shared::IrradianceRecord> records;
    records.reserve(records_.size());
    for (size_t i = 0; i < records_.size(); ++i) {
        records.push_back(device_record(i));
    }
    return records;
}

RecordGridData RecordStore::build_grid(size_t max_cells) const {
    RecordGridData data;
    if (records_.empty()) {
        data.grid.origin = {0, 0, 0, 0};
        data.grid.inv_cell = {1, 1, 1, 0};
        data.grid.dims = {1, 1, 1, 1};
        data.cell_start = {0, 0};
        return data;
    }
    glm::vec3 lower(std::numeric_limits<float>::max());
    glm::vec3 upper(-std::numeric_limits<float>::max());
    std::vector<float> influence(records_.size());
    for (size_t i = 0; i < records_.size(); ++i) {
        influence[i] = accuracy_ * clamped_radius(records_[i]);
        lower = glm::min(lower, records_[i].position - glm::vec3(influence[i]));
        upper = glm::max(upper, records_[i].position + glm::vec3(influence[i]));
    }
    std::vector<float> sorted = influence;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const glm::vec3 extent = glm::max(upper - lower, glm::vec3(1e-6f));
    // Cells about twice the median influence radius, fewer if that would make too many.
    float cell = std::max(2.0f * sorted[sorted.size() / 2], 1e-6f * glm::length(extent));
    auto count_for = [&](float size) {
        const glm::vec3 dims = glm::ceil(extent / size);
        return static_cast<double>(dims.x) * dims.y * dims.z;
    };
    while (count_for(cell) > static_cast<double>(max_cells)) {
        cell *= 1.25f;
    }
    const glm::ivec3 dims = glm::max(glm::ivec3(glm::ceil(extent / cell)), glm::ivec3(1));
    const size_t cells = static_cast<size_t>(dims.x) * dims.y * dims.z;
    data.grid.origin = float4_of(lower);
    data.grid.inv_cell = float4_of(glm::vec3(1.0f / cell));
    data.grid.dims = {dims.x, dims.y, dims.z, static_cast<int>(cells)};

    // Counting sort of (cell, record) pairs; records ascend within each cell.
    auto cell_range = [&](size_t i, glm::ivec3& from, glm::ivec3& to) {
        from = glm::clamp(glm::ivec3((records_[i].position - influence[i] - lower) / cell),
                          glm::ivec3(0), dims - 1);
        to = glm::clamp(glm::ivec3((records_[i].position + influence[i] - lower) / cell),
                        glm::ivec3(0), dims - 1);
    };
    std::vector<int> counts(cells + 1, 0);
    for (size_t i = 0; i < records_.size(); ++i) {
        glm::ivec3 from, to;
        cell_range(i, from, to);
        for (int z = from.z; z <= to.z; ++z) {
            for (int y = from.y; y <= to.y; ++y) {
                for (int x = from.x; x <= to.x; ++x) {
                    ++counts[(static_cast<size_t>(z) * dims.y + y) * dims.x + x + 1];
                }
            }
        }
    }
    for (size_t c = 0; c < cells; ++c) {
        counts[c + 1] += counts[c];
    }
    if (counts[cells] > std::numeric_limits<int>::max() / 2) {
        throw Error("irradiance cache grid: too many record references");
    }
    data.cell_start = counts;
    data.cell_records.assign(static_cast<size_t>(counts[cells]), 0);
    std::vector<int> fill(counts.begin(), counts.end() - 1);
    for (size_t i = 0; i < records_.size(); ++i) {
        glm::ivec3 from, to;
        cell_range(i, from, to);
        for (int z = from.z; z <= to.z; ++z) {
            for (int y = from.y; y <= to.y; ++y) {
                for (int x = from.x; x <= to.x; ++x) {
                    const size_t c = (static_cast<size_t>(z) * dims.y + y) * dims.x + x;
                    data.cell_records[fill[c]++] = static_cast<int>(i);
                }
            }
        }
    }
    return data;
}

void RecordStore::restore(std::vector<CacheRecord> records) {
    records_ = std::move(records);
    classes_.clear();
    for (uint32_t i = 0; i < records_.size(); ++i) {
        index_record(i);
    }
}

}  // namespace rc
