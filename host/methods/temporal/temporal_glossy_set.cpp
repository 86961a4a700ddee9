#include "methods/temporal/temporal_glossy_set.h"

#include <string>
#include <utility>

#include "methods/temporal/temporal_lifespan.h"
#include "util/error.h"

namespace rc {

TemporalGlossySet::TemporalGlossySet(TemporalOptions temporal, int first_frame, int last_frame)
    : temporal_(temporal), first_frame_(first_frame), last_frame_(last_frame) {}

void TemporalGlossySet::select(int frame, std::vector<size_t>* serving,
                               std::vector<size_t>* expired) const {
    for (size_t id = 0; id < records_.size(); ++id) {
        const TemporalGlossyRecord& r = records_[id];
        const long long end = static_cast<long long>(r.created) + r.lifespan;
        if (frame < end) {
            serving->push_back(id);
        } else if (frame == end) {
            expired->push_back(id);
        }
    }
}

std::vector<size_t> TemporalGlossySet::staying(const std::vector<size_t>& expired) const {
    std::vector<size_t> staying;
    for (size_t id : expired) {
        if (!records_[id].site_moves) {
            staying.push_back(id);
        }
    }
    return staying;
}

TemporalGlossySet::Replacements TemporalGlossySet::replacements(
    const std::vector<size_t>& candidates, const std::vector<uint8_t>& used) const {
    Replacements r;
    for (size_t i = 0; i < candidates.size(); ++i) {
        if (used[i] != 0) {
            r.records.push_back(candidates[i]);
            r.sites.push_back(records_[candidates[i]].site);
            r.streams.push_back(records_[candidates[i]].stream);
        }
    }
    return r;
}

TemporalGlossyFrameStats& TemporalGlossySet::adopt(
    int frame, const RecordStore& placed, const std::vector<size_t>& serving, size_t expired,
    std::vector<CarriedGlossyRecord> carried, std::vector<std::vector<float>> payloads,
    const std::vector<size_t>& replaced, size_t per_channel) {
    if (placed.size() != serving.size() + carried.size() || payloads.size() != carried.size()) {
        throw Error("temporal glossy caching: " + std::to_string(placed.size()) +
                    " records placed, " + std::to_string(serving.size() + carried.size()) +
                    " expected");
    }
    // Step 1: the serving records as neighbor clamping left them.
    for (size_t i = 0; i < serving.size(); ++i) {
        records_[serving[i]].record = placed.records()[i];
        records_[serving[i]].host = placed.host_data()[i];
    }
    // Step 2: the new records, their lifespans by their change (eqs. 9-12), the replacements
    // linked to the records they replace (§5).
    const size_t first_new = records_.size();
    double lifespans = 0.0;
    for (size_t k = 0; k < carried.size(); ++k) {
        const size_t i = serving.size() + k;
        TemporalGlossyRecord r;
        r.record = placed.records()[i];
        r.host = placed.host_data()[i];
        r.payload = std::move(payloads[k]);
        r.next = std::move(carried[k].next);
        r.site = carried[k].site;
        r.stream = carried[k].stream;
        r.created = frame;
        r.site_moves = carried[k].site_moves;
        const float change = glossy_temporal_change(r.payload, r.next, per_channel);
        r.lifespan = temporal_lifespan_in_clip(change, temporal_, r.site_moves, frame, last_frame_);
        lifespans += r.lifespan;
        if (k < replaced.size()) {
            records_[replaced[k]].successor = static_cast<int>(records_.size());
        }
        records_.push_back(std::move(r));
    }
    // Step 3: the frame's serving records, for its shading.
    std::vector<Serving> now;
    for (size_t i = 0; i < placed.size(); ++i) {
        const size_t id = i < serving.size() ? serving[i] : first_new + (i - serving.size());
        now.push_back({id, placed.records()[i], placed.host_data()[i]});
    }
    TemporalGlossyFrameStats stats;
    stats.reused = serving.size();
    stats.recomputed = replaced.size();
    stats.dropped = expired - replaced.size();
    stats.created = carried.size() - replaced.size();
    stats.mean_new_lifespan =
        carried.empty() ? 0.0 : lifespans / static_cast<double>(carried.size());
    stats.records = now.size();
    serving_.push_back(std::move(now));
    frame_stats_.push_back(stats);
    return frame_stats_.back();
}

const std::vector<TemporalGlossySet::Serving>& TemporalGlossySet::serving(int frame) const {
    const size_t index = static_cast<size_t>(frame - first_frame_);
    if (index >= serving_.size()) {
        throw Error("temporal glossy caching: frame " + std::to_string(frame) +
                    " shaded before it was placed");
    }
    return serving_[index];
}

std::vector<float> TemporalGlossySet::payload_at(size_t record, int frame) const {
    const TemporalGlossyRecord& r = records_[record];
    const TemporalGlossyRecord* successor =
        r.successor >= 0 ? &records_[static_cast<size_t>(r.successor)] : nullptr;
    return glossy_temporal_payload(r, successor, frame, temporal_.gradients);
}

nlohmann::json TemporalGlossySet::frame_stats(int frame) const {
    const TemporalGlossyFrameStats& s = frame_stats_.at(static_cast<size_t>(frame - first_frame_));
    return {{"records", s.records},         {"reused", s.reused},
            {"recomputed", s.recomputed},   {"dropped", s.dropped},
            {"created", s.created},         {"mean_new_lifespan", s.mean_new_lifespan},
            {"record_rays", s.record_rays}, {"seconds", {{"placement", s.placement_seconds}}}};
}

}  // namespace rc
