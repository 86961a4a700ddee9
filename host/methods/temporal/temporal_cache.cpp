#include "methods/temporal/temporal_cache.h"

#include <algorithm>
#include <cstring>

#include "methods/caching/pipeline_stats.h"
#include "methods/caching/record_level_source.h"
#include "util/error.h"
#include "util/timing.h"

namespace rc {
namespace {

// Replacement records computed together (TemporalIrradianceCache::place_frame).
constexpr size_t kReplacementGroup = 32;

// A store holding `ids` of `records` with the given shared parts and host data, payloads `payload`.
template <class PayloadOf>
RecordStore store_of(float accuracy, size_t count, const PayloadOf& payload_of,
                     std::vector<shared::Record> shared_parts, std::vector<RecordHostData> host) {
    RecordStore store = irradiance_store(accuracy);
    std::vector<std::byte> payloads(count * sizeof(shared::IrradiancePayload));
    for (size_t i = 0; i < count; ++i) {
        const shared::IrradiancePayload p = payload_of(i);
        std::memcpy(payloads.data() + i * sizeof p, &p, sizeof p);
    }
    store.restore(std::move(shared_parts), std::move(host), std::move(payloads));
    return store;
}

// Shows every batch of records to the one-frame reprojection and the first level's also to the
// two-frame one when there is one (--temporal-lifespan departure: deeper records' lifespans stay
// by change, their values being held).
class ReprojectionPair final : public RecordBatchObserver {
   public:
    ReprojectionPair(RecordBatchObserver& one_frame, RecordBatchObserver* two_frames)
        : one_frame_(one_frame), two_frames_(two_frames) {}
    void observe(const RecordBatch& batch) override {
        one_frame_.observe(batch);
        if (two_frames_ != nullptr && batch.params.level == 0) {
            two_frames_->observe(batch);
        }
    }

   private:
    RecordBatchObserver& one_frame_;
    RecordBatchObserver* two_frames_;
};

}  // namespace

TemporalIrradianceCache::TemporalIrradianceCache(PipelineSettings ic, TemporalOptions temporal,
                                                 int first_frame, int frame_count)
    : ic_(std::move(ic)),
      temporal_(temporal),
      first_frame_(first_frame),
      // In 64 bits: first + count overflows int when the run ends at the largest frame number.
      last_frame_(
          static_cast<int>(static_cast<long long>(first_frame) + std::max(frame_count, 1) - 1)),
      placed_until_(first_frame - 1),
      shaded_until_(first_frame - 1),
      levels_(static_cast<size_t>(std::max(ic_.bounces, 1))) {}

RecordStore TemporalIrradianceCache::serving_store(int level, int frame,
                                                   std::vector<size_t>* serving,
                                                   std::vector<size_t>* expired) const {
    const std::vector<TemporalRecord>& records = levels_[static_cast<size_t>(level)].records;
    std::vector<shared::Record> shared_parts;
    std::vector<RecordHostData> host;
    for (size_t id = 0; id < records.size(); ++id) {
        const TemporalRecord& r = records[id];
        const long long end = static_cast<long long>(r.created) + r.lifespan;
        if (frame < end) {
            serving->push_back(id);
            shared_parts.push_back(r.computed.record);
            host.push_back(r.computed.host);
        } else if (frame == end) {
            expired->push_back(id);
        }
    }
    return store_of(
        ic_.accuracy, serving->size(),
        [&](size_t i) { return records[(*serving)[i]].computed.payload; }, std::move(shared_parts),
        std::move(host));
}

std::vector<size_t> TemporalIrradianceCache::still_used(CachePipeline& cache,
                                                        const std::vector<size_t>& expired) {
    const std::vector<TemporalRecord>& records = levels_[0].records;
    std::vector<size_t> candidates;
    std::vector<shared::Record> shared_parts;
    std::vector<RecordHostData> host;
    for (size_t id : expired) {
        if (!records[id].site_moves) {  // its surface has left: nothing to replace
            candidates.push_back(id);
            shared_parts.push_back(records[id].computed.record);
            host.push_back(records[id].computed.host);
        }
    }
    const std::vector<uint8_t> used = cache.records_used(store_of(
        ic_.accuracy, candidates.size(),
        [&](size_t i) { return records[candidates[i]].computed.payload; }, std::move(shared_parts),
        std::move(host)));
    std::vector<size_t> kept;
    for (size_t i = 0; i < candidates.size(); ++i) {
        if (used[i] != 0) {
            kept.push_back(candidates[i]);
        }
    }
    return kept;
}

int TemporalIrradianceCache::new_lifespan(TemporalRecord* r, const CarriedRecord* ahead, int frame,
                                          bool still) const {
    // Nothing moves and no light changes: the reprojection gives E_1 = E_0 bit for bit and the
    // temporal weight (eq. 9) stays infinite while that lasts; delta t_max (eq. 12) bounds such
    // a record only when the user sets it.
    if (still && !r->site_moves && !temporal_.max_frames_given) {
        r->until_motion = true;
        return last_frame_ - frame + 1;
    }
    const float change = temporal_change(r->computed.payload, r->next);
    const int lifespan =
        ahead != nullptr
            ? departure_lifespan(temporal_curvature(r->computed.payload, r->next, ahead->next),
                                 temporal_, r->site_moves)
            : temporal_lifespan(change, temporal_, r->site_moves);
    return lifespan_in_clip(lifespan, change, temporal_, frame, last_frame_);
}

void TemporalIrradianceCache::end_still_records(int frame) {
    for (Level& level : levels_) {
        for (TemporalRecord& r : level.records) {
            const long long end = static_cast<long long>(r.created) + r.lifespan;
            if (r.until_motion && r.created <= frame && end > frame + 1LL) {
                r.lifespan = static_cast<int>(static_cast<long long>(frame) + 1 - r.created);
            }
        }
    }
}

double TemporalIrradianceCache::adopt(int level, int frame, const RecordStore& placed,
                                      const std::vector<size_t>& serving,
                                      const std::vector<CarriedRecord>& carried,
                                      const std::vector<CarriedRecord>& ahead,
                                      const std::vector<size_t>& replaced, bool still) {
    std::vector<TemporalRecord>& records = levels_[static_cast<size_t>(level)].records;
    if (placed.size() != serving.size() + carried.size()) {
        throw Error("temporal caching: level " + std::to_string(level) + " holds " +
                    std::to_string(placed.size()) + " records, " +
                    std::to_string(serving.size() + carried.size()) + " expected");
    }
    if (!ahead.empty() && ahead.size() != carried.size()) {
        throw Error("temporal caching: " + std::to_string(ahead.size()) +
                    " records reprojected two frames ahead, " + std::to_string(carried.size()) +
                    " one frame");
    }
    for (size_t i = 0; i < serving.size(); ++i) {
        TemporalRecord& r = records[serving[i]];
        r.computed.record = placed.records()[i];
        r.computed.host = placed.host_data()[i];
    }
    double lifespans = 0.0;
    for (size_t k = 0; k < carried.size(); ++k) {
        const size_t i = serving.size() + k;
        TemporalRecord r;
        r.computed.record = placed.records()[i];
        r.computed.host = placed.host_data()[i];
        r.computed.payload = placed.payload<shared::IrradiancePayload>(i);
        r.site = carried[k].site;
        r.created = frame;
        r.next = carried[k].next;
        r.site_moves = carried[k].site_moves;
        r.lifespan = new_lifespan(&r, ahead.empty() ? nullptr : &ahead[k], frame, still);
        lifespans += r.lifespan;
        // A record that served until motion held its value until then: it does not blend towards
        // a replacement that sees the motion.
        if (k < replaced.size() && !records[replaced[k]].until_motion) {
            records[replaced[k]].successor = static_cast<int>(records.size());
        }
        records.push_back(r);
    }
    return carried.empty() ? 0.0 : lifespans / static_cast<double>(carried.size());
}

std::unique_ptr<TemporalReprojection> TemporalIrradianceCache::two_frames_ahead(
    const FrameScene& frame) {
    if (temporal_.lifespan != TemporalLifespan::kDeparture) {
        return nullptr;
    }
    if (!ahead_) {
        ahead_.emplace(frame.scene);
    }
    ahead_->set_frame(static_cast<double>(frame.frame) + 2.0);
    return std::make_unique<TemporalReprojection>(frame, *ahead_, temporal_.hole_passes);
}

std::vector<uint8_t> TemporalIrradianceCache::moving_into_or_out(
    const TemporalReprojection& reprojection) {
    // At the sequence's last frame the next pose may be the same: the motion into it still counts.
    std::vector<uint8_t> moving = reprojection.moves();
    for (size_t p = 0; p < std::min(moving.size(), moved_before_.size()); ++p) {
        moving[p] |= moved_before_[p];
    }
    moved_before_ = reprojection.moves();
    return moving;
}

void TemporalIrradianceCache::place_frame(const FrameScene& frame) {
    const auto start = SteadyClock::now();
    const int t = frame.frame;
    TemporalFrameStats stats;
    // The scene one frame later, for the reprojection.
    if (!next_) {
        next_.emplace(frame.scene);
    }
    next_->set_frame(static_cast<double>(t) + 1.0);
    TemporalReprojection reprojection(frame, *next_, temporal_.hole_passes);
    stats.moving_primitives = reprojection.moving_primitives();
    PipelineSettings options = ic_;
    const std::unique_ptr<TemporalReprojection> two_frames = two_frames_ahead(frame);
    ReprojectionPair observers(reprojection, two_frames.get());
    PipelinePlugins plugins;
    plugins.observer = &observers;
    std::vector<uint8_t> moving = moving_into_or_out(reprojection);
    const bool still = reprojection.still();
    if (!still) {
        end_still_records(t);
    }
    if (!temporal_.cache_moving_hits) {
        plugins.uncached_primitives = std::move(moving);
    }
    options.records_overlay = false;
    CachePipeline cache(frame, std::move(plugins));
    cache.begin(options);

    // Every level's serving records stay. An expired first-level record is computed again in
    // its place if it still serves the image (the report's §5), else dropped; expired deeper
    // records are dropped.
    const int levels = cache.levels();
    std::vector<std::vector<size_t>> serving(static_cast<size_t>(levels));
    std::vector<std::vector<size_t>> expired(static_cast<size_t>(levels));
    for (int level = 0; level < levels; ++level) {
        const size_t l = static_cast<size_t>(level);
        RecordStore store = serving_store(level, t, &serving[l], &expired[l]);
        cache.set_records(level, std::move(store), levels_[l].next_stream);
    }
    const auto usage_start = SteadyClock::now();
    const std::vector<size_t> replaced = still_used(cache, expired[0]);
    stats.usage_seconds = seconds_since(usage_start);
    std::vector<RecordSite> sites;
    for (size_t id : replaced) {
        sites.push_back(levels_[0].records[id].site);
    }
    // Replacements, then new records where the image is not covered.
    // In small groups, oldest first: a group's deeper-level records cover the next group's
    // hemisphere hits, as placement's coarse-to-fine passes do. (Deeper records are placed at the
    // spacing bound of the hits, then grow to their own radius: hits placed all at once, before
    // any grows, took 2.5x the second-level records placement does on moving-light.)
    for (size_t begin = 0; begin < sites.size(); begin += kReplacementGroup) {
        const size_t end = std::min(sites.size(), begin + kReplacementGroup);
        cache.add_records(std::vector<RecordSite>(sites.begin() + static_cast<long>(begin),
                                                  sites.begin() + static_cast<long>(end)));
    }
    cache.place();

    for (int level = 0; level < levels; ++level) {
        const size_t l = static_cast<size_t>(level);
        levels_[l].next_stream = cache.next_stream(level);
        const std::vector<CarriedRecord> carried = reprojection.take(level);
        const std::vector<CarriedRecord> ahead =
            two_frames && level == 0 ? two_frames->take(0) : std::vector<CarriedRecord>{};
        const double lifespan = adopt(level, t, cache.store(level), serving[l], carried, ahead,
                                      level == 0 ? replaced : std::vector<size_t>{}, still);
        size_t on_moving = 0;
        for (const CarriedRecord& c : carried) {
            on_moving += c.site_moves ? 1 : 0;
        }
        if (level == 0) {
            stats.on_moving_surfaces = on_moving;
            stats.reused = serving[0].size();
            stats.recomputed = replaced.size();
            stats.dropped = expired[0].size() - replaced.size();
            stats.created = carried.size() - replaced.size();
            stats.mean_new_lifespan = lifespan;
        } else {
            stats.deeper.push_back(
                {serving[l].size(), carried.size(), expired[l].size(), on_moving, lifespan});
        }
    }
    // The first level as it serves this frame, for shading.
    std::vector<Serving> now;
    const RecordStore& placed = cache.store(0);
    for (size_t i = 0; i < placed.size(); ++i) {
        const size_t id =
            i < serving[0].size() ? serving[0][i] : levels_[0].records.size() - placed.size() + i;
        now.push_back({id, placed.records()[i], placed.host_data()[i]});
    }
    stats.records = now.size();
    const PipelineStats placement = cache.current_stats();
    stats.record_rays = placement.record_rays;
    stats.placement = placement;
    stats.placement_seconds = seconds_since(start);
    stats.reprojection_seconds =
        reprojection.seconds() + (two_frames ? two_frames->seconds() : 0.0);
    serving_.push_back(std::move(now));
    frame_stats_.push_back(stats);
    // The glossy lobes' radiance records, whose hemisphere rays read this frame's first level.
    if (glossy_ != nullptr) {
        const RecordLevelSource first_level(frame.context, cache.store(0), kRecordMaxWeight);
        glossy_->place_frame(frame, reprojection.motion(), cache.first_level_params(),
                             cache.camera(), first_level);
    }
}

void TemporalIrradianceCache::place_through(int last, const FrameScene& frame,
                                            const FrameHooks& hooks) {
    // long long: a range ending at the largest frame number stops.
    for (long long next = static_cast<long long>(placed_until_) + 1; next <= last; ++next) {
        const int f = static_cast<int>(next);
        if (f == frame.frame) {
            place_frame(frame);
        } else if (hooks.visit_frame) {
            hooks.visit_frame(f, [&](const FrameScene& other) { place_frame(other); });
        } else {
            throw Error("temporal caching: frame " + std::to_string(f) +
                        " must be placed before frame " + std::to_string(frame.frame) +
                        " is shaded, and the caller offers no other frame");
        }
        placed_until_ = f;
    }
}

FrameResult TemporalIrradianceCache::shade_frame(const FrameScene& frame) {
    const int t = frame.frame;
    const std::vector<Serving>& serving = serving_[static_cast<size_t>(t - first_frame_)];
    const std::vector<TemporalRecord>& records = levels_[0].records;
    std::vector<shared::Record> shared_parts;
    std::vector<RecordHostData> host;
    for (const Serving& s : serving) {
        shared_parts.push_back(s.shared);
        host.push_back(s.host);
    }
    const TemporalGradients gradients = temporal_.gradients;
    RecordStore store = store_of(
        ic_.accuracy, serving.size(),
        [&](size_t i) {
            const TemporalRecord& r = records[serving[i].record];
            const TemporalRecord* successor =
                r.successor >= 0 ? &records[static_cast<size_t>(r.successor)] : nullptr;
            return temporal_payload(r, successor, t, gradients);
        },
        std::move(shared_parts), std::move(host));
    PipelineSettings options = ic_;
    std::unique_ptr<GlossyCache> glossy;
    if (glossy_ != nullptr) {
        glossy = glossy_->shading(frame);
    }
    CachePipeline cache(frame, {.lobes = glossy.get()});
    cache.begin(options);
    cache.set_records(0, std::move(store), 0);
    PipelineStats stats;
    FrameResult result;
    result.image = cache.finish(options, &stats);
    result.spp = ic_.spp;
    const TemporalFrameStats& placed = frame_stats_[static_cast<size_t>(t - first_frame_)];
    PipelineStats combined = placed.placement;
    combined.gbuffer_seconds += stats.gbuffer_seconds;
    combined.splatting_seconds = stats.splatting_seconds;
    combined.shading_seconds = stats.shading_seconds;
    combined.shading_rays = stats.shading_rays;
    combined.cache_bytes = stats.cache_bytes;
    combined.records = stats.records;
    if (!combined.level_records.empty()) {
        combined.level_records[0] = stats.records;
    }
    result.rays = placed.record_rays + stats.shading_rays;
    result.nonfinite_samples = stats.nonfinite_samples;
    result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
    add_irradiance_cache_stats(combined, ic_, &result.stats);
    result.stats["temporal"] = {{"gradients", temporal_gradients_name(temporal_.gradients)},
                                {"lifespan", temporal_lifespan_name(temporal_.lifespan)},
                                {"records", placed.records},
                                {"reused", placed.reused},
                                {"recomputed", placed.recomputed},
                                {"dropped", placed.dropped},
                                {"created", placed.created},
                                {"on_moving_surfaces", placed.on_moving_surfaces},
                                {"mean_new_lifespan", placed.mean_new_lifespan},
                                {"moving_primitives", placed.moving_primitives},
                                {"record_rays", placed.record_rays},
                                {"seconds",
                                 {{"placement", placed.placement_seconds},
                                  {"reprojection", placed.reprojection_seconds},
                                  {"usage", placed.usage_seconds}}}};
    nlohmann::json deeper = nlohmann::json::array();
    for (size_t l = 0; l < placed.deeper.size(); ++l) {
        deeper.push_back({{"level", l + 1},
                          {"reused", placed.deeper[l].reused},
                          {"created", placed.deeper[l].created},
                          {"dropped", placed.deeper[l].dropped},
                          {"on_moving_surfaces", placed.deeper[l].on_moving_surfaces},
                          {"mean_new_lifespan", placed.deeper[l].mean_new_lifespan}});
    }
    result.stats["temporal"]["deeper_levels"] = deeper;
    if (glossy_ != nullptr) {
        const nlohmann::json radiance = glossy_->frame_stats(t);
        result.rays += radiance["record_rays"].get<uint64_t>();
        result.stats["temporal"]["radiance"] = radiance;
    }
    return result;
}

FrameResult TemporalIrradianceCache::render_frame(const FrameScene& frame,
                                                  const FrameHooks& hooks) {
    if (frame.frame != static_cast<long long>(shaded_until_) + 1) {
        throw Error("temporal caching: frame " + std::to_string(frame.frame) + " asked for after " +
                    std::to_string(shaded_until_) + "; frames come in order from " +
                    std::to_string(first_frame_));
    }
    const int lookahead =
        temporal_.gradients == TemporalGradients::kInterpolated
            ? static_cast<int>(std::min<long long>(
                  last_frame_, static_cast<long long>(frame.frame) + temporal_.max_frames))
            : frame.frame;
    place_through(std::max(lookahead, frame.frame), frame, hooks);
    FrameResult result = shade_frame(frame);
    shaded_until_ = frame.frame;
    return result;
}

}  // namespace rc
