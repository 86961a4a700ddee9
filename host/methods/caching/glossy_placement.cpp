#include "methods/caching/glossy_placement.h"

#include <algorithm>

#include "methods/caching/placement_passes.h"
#include "methods/caching/record_grid.h"
#include "util/glm_helpers.h"
#include "util/log.h"
#include "util/timing.h"

namespace rc {

int first_candidate_stride(uint32_t i, uint32_t width, uint32_t spp) {
    const uint32_t pixel = i / spp;
    if (i % spp == 0) {
        for (int stride : {16, 8, 4, 2}) {
            if ((pixel % width) % stride == 0 && (pixel / width) % stride == 0) {
                return stride;
            }
        }
    }
    return 1;
}

std::vector<unsigned> next_streams(size_t count, unsigned* next) {
    std::vector<unsigned> streams(count);
    for (unsigned& stream : streams) {
        stream = (*next)++;
    }
    return streams;
}

GlossyPlacement::GlossyPlacement(Context& context)
    : context_(context),
      served_kernel_(context.kernel("caching/glossy_placement.cl", "rc_served_queries")),
      select_kernel_(context.kernel("caching/glossy_placement.cl", "rc_select_queries")),
      uncovered_kernel_(context.kernel("caching/glossy_placement.cl", "rc_uncovered")),
      used_kernel_(context.kernel("caching/glossy_placement.cl", "rc_records_used")) {}

std::vector<uint8_t> GlossyPlacement::records_used(const Buffer<shared::RcQuery>& queries,
                                                   const RecordStore& store) {
    if (store.size() == 0) {
        return {};
    }
    const RecordGridData data = build_record_grid(store.records(), store.accuracy());
    const Buffer<shared::Record> records(context_, store.records(), "glossy_used_records");
    const Buffer<int> cell_start(context_, data.cell_start, "glossy_used_cell_start");
    const Buffer<int> cell_records(context_, data.cell_records, "glossy_used_cell_records");
    Buffer<unsigned> used(context_, store.size(), "glossy_records_used");
    used.fill_zero();
    context_.launch(used_kernel_, queries.size(), store.accuracy(), kRecordMaxWeight, data.grid,
                    cell_start, cell_records, records, queries, used);
    const std::vector<unsigned> flags = used.download();
    return std::vector<uint8_t>(flags.begin(), flags.end());
}

void GlossyPlacement::select_served(const Buffer<shared::RcQuery>& queries,
                                    GlossyPlacementStats* stats) {
    Buffer<unsigned> indices(context_, queries.size(), "glossy_served");
    Buffer<unsigned> counts(context_, 3, "glossy_served_counts");
    counts.fill_zero();
    context_.launch(served_kernel_, queries.size(), queries, indices, counts);
    const std::vector<unsigned> count = counts.download();
    stats->glossy_samples = count[1];
    stats->fallback_samples = count[2];
    served_.assign(count[0], 0);
    copies_.clear();
    if (served_.empty()) {
        return;
    }
    indices.read(served_.data(), served_.size() * sizeof(uint32_t));
    std::sort(served_.begin(), served_.end());  // appended in any order
    const Buffer<unsigned> sorted(context_, served_, "glossy_served_sorted");
    Buffer<shared::RcQuery> selected(context_, served_.size(), "glossy_served_queries");
    context_.launch(select_kernel_, served_.size(), queries, sorted, selected);
    copies_ = selected.download();
}

const shared::RcQuery& GlossyPlacement::copy(uint32_t index) const {
    return copies_[static_cast<size_t>(std::lower_bound(served_.begin(), served_.end(), index) -
                                       served_.begin())];
}

std::vector<uint32_t> GlossyPlacement::uncovered(const Buffer<shared::RcQuery>& queries,
                                                 const RecordStore& store,
                                                 const std::vector<uint32_t>& candidates) {
    const RecordGridData data = build_record_grid(store.records(), store.accuracy());
    const Buffer<shared::Record> records(context_, store.records(), "glossy_records");
    const Buffer<int> cell_start(context_, data.cell_start, "glossy_cell_start");
    const Buffer<int> cell_records(context_, data.cell_records, "glossy_cell_records");
    const Buffer<unsigned> candidate_buffer(context_, candidates, "glossy_candidates");
    Buffer<unsigned> out(context_, candidates.size(), "glossy_uncovered");
    Buffer<unsigned> count(context_, 1, "glossy_uncovered_count");
    count.fill_zero();
    context_.launch(uncovered_kernel_, candidates.size(), store.accuracy(), kRecordMaxWeight,
                    data.grid, cell_start, cell_records, records, queries, candidate_buffer, out,
                    count);
    std::vector<uint32_t> indices(count.download()[0]);
    if (!indices.empty()) {
        out.read(indices.data(), indices.size() * sizeof(uint32_t));
    }
    std::sort(indices.begin(), indices.end());  // appended in any order
    return indices;
}

void GlossyPlacement::cover(const Buffer<shared::RcQuery>& queries, const RecordStore& store,
                            const std::vector<uint32_t>& candidates, int stride, bool until_covered,
                            Spacing min_spacing, const AddRecords& add_records,
                            GlossyPlacementStats* stats) {
    if (candidates.empty()) {
        return;
    }
    std::vector<uint32_t> open;
    auto start = SteadyClock::now();
    // Step 1 of a pass: the candidates no record covers, with their minimum influence radii.
    const auto find = [&]() {
        start = SteadyClock::now();
        open = uncovered(queries, store, candidates);
        UncoveredCandidates found;
        found.positions.resize(open.size());
        found.normals.resize(open.size());
        found.min_influence.resize(open.size());
        for (size_t c = 0; c < open.size(); ++c) {
            const shared::RcQuery& q = copy(open[c]);
            found.positions[c] = vec3_of(q.position);
            found.normals[c] = vec3_of(q.normal);
            found.min_influence[c] = store.accuracy() * spacing_bound(min_spacing, q.footprint);
        }
        return found;
    };
    // Step 2: records at the candidates thinning kept.
    const auto add = [&](const std::vector<size_t>& chosen) {
        std::vector<shared::RcQuery> sites;
        for (size_t c : chosen) {
            sites.push_back(copy(open[c]));
        }
        stats->placement_seconds += seconds_since(start);
        stats->passes.push_back({0, stride, candidates.size(), open.size(), sites.size()});
        start = SteadyClock::now();
        add_records(sites);
        stats->record_seconds += seconds_since(start);
        start = SteadyClock::now();
    };
    const size_t left = run_placement_passes(until_covered, find, add);
    stats->placement_seconds += seconds_since(start);
    if (left > 0) {
        log_warning("glossy placement: " + std::to_string(left) +
                    " camera sample(s) left uncovered after " +
                    std::to_string(kMaxPlacementPasses) +
                    " placement passes (records smaller than the scene's float precision?)");
    }
}

void GlossyPlacement::place(const Buffer<shared::RcQuery>& queries, const RecordStore& store,
                            uint32_t width, uint32_t spp, Spacing min_spacing,
                            const AddRecords& add_records, GlossyPlacementStats* stats) {
    select_served(queries, stats);
    for (int stride : {16, 8, 4, 2, 1}) {
        std::vector<uint32_t> candidates;
        for (uint32_t i : served_) {
            if (first_candidate_stride(i, width, spp) >= stride) {
                candidates.push_back(i);
            }
        }
        cover(queries, store, candidates, stride, stride == 1, min_spacing, add_records, stats);
    }
}

}  // namespace rc
