#include "methods/radiance_cache/temporal_radiance_cache.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "methods/radiance_cache/radiance_records.h"
#include "methods/radiance_cache/tc_radiance_reprojection.h"
#include "methods/temporal/temporal_lifespan.h"
#include "util/error.h"
#include "util/timing.h"

namespace rc {
namespace {

// A store of radiance records of order `order` holding the given parts and payloads.
RecordStore radiance_store_of(float accuracy, int order, std::vector<shared::Record> records,
                              std::vector<RecordHostData> host,
                              const std::vector<const std::vector<float>*>& payloads) {
    RecordStore store = radiance_store(accuracy, order);
    const size_t floats = radiance_payload_floats(order);
    std::vector<std::byte> bytes(payloads.size() * floats * sizeof(float));
    for (size_t i = 0; i < payloads.size(); ++i) {
        std::memcpy(bytes.data() + i * floats * sizeof(float), payloads[i]->data(),
                    floats * sizeof(float));
    }
    store.restore(std::move(records), std::move(host), std::move(bytes));
    return store;
}

// The glossy cache of one frame's shading: radiance caching's queries and splat over a given
// store, no placement.
class TemporalRadianceShading final : public GlossyCache {
   public:
    TemporalRadianceShading(const FrameScene& frame, const RadianceCacheOptions& options,
                            std::shared_ptr<const BrdfTables> tables, RecordStore store)
        : cache_(frame, options, std::move(tables)) {
        cache_.set_store(std::move(store), 0);
    }

    Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                  const shared::CameraParams& camera,
                                                  const RadianceSource&) override {
        return cache_.splat(cache_.queries(params, camera));
    }
    std::vector<FilmLayer> layers() const override { return cache_.layers(); }
    uint64_t rays() const override { return cache_.rays(); }
    double record_seconds() const override { return cache_.record_seconds(); }

   private:
    RadianceCache cache_;
};

}  // namespace

TemporalRadianceCache::TemporalRadianceCache(RadianceCacheOptions options, TemporalOptions temporal,
                                             int first_frame, int last_frame)
    : options_(std::move(options)),
      temporal_(temporal),
      first_frame_(first_frame),
      last_frame_(last_frame) {}

RecordStore TemporalRadianceCache::serving_store(int frame, int order, std::vector<size_t>* serving,
                                                 std::vector<size_t>* expired) const {
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    std::vector<const std::vector<float>*> payloads;
    for (size_t id = 0; id < records_.size(); ++id) {
        const TemporalRadianceRecord& r = records_[id];
        const long long end = static_cast<long long>(r.created) + r.lifespan;
        if (frame < end) {
            serving->push_back(id);
            parts.push_back(r.record);
            host.push_back(r.host);
            payloads.push_back(&r.payload);
        } else if (frame == end) {
            expired->push_back(id);
        }
    }
    return radiance_store_of(options_.accuracy, order, std::move(parts), std::move(host), payloads);
}

double TemporalRadianceCache::adopt(int frame, int order, const RecordStore& placed,
                                    const std::vector<size_t>& serving,
                                    std::vector<CarriedRadianceRecord> carried,
                                    const std::vector<size_t>& replaced) {
    if (placed.size() != serving.size() + carried.size()) {
        throw Error("temporal radiance caching: " + std::to_string(placed.size()) +
                    " records placed, " + std::to_string(serving.size() + carried.size()) +
                    " expected");
    }
    for (size_t i = 0; i < serving.size(); ++i) {
        records_[serving[i]].record = placed.records()[i];
        records_[serving[i]].host = placed.host_data()[i];
    }
    const size_t floats = radiance_payload_floats(order);
    double lifespans = 0.0;
    for (size_t k = 0; k < carried.size(); ++k) {
        const size_t i = serving.size() + k;
        TemporalRadianceRecord r;
        r.record = placed.records()[i];
        r.host = placed.host_data()[i];
        const auto* data = reinterpret_cast<const float*>(placed.payload_data(i));
        r.payload.assign(data, data + floats);
        r.next = std::move(carried[k].next);
        r.site = carried[k].site;
        r.stream = carried[k].stream;
        r.created = frame;
        r.site_moves = carried[k].site_moves;
        const float change = radiance_temporal_change(r.payload, r.next, order);
        r.lifespan = temporal_lifespan_in_clip(change, temporal_, r.site_moves, frame, last_frame_);
        lifespans += r.lifespan;
        if (k < replaced.size()) {
            records_[replaced[k]].successor = static_cast<int>(records_.size());
        }
        records_.push_back(std::move(r));
    }
    return carried.empty() ? 0.0 : lifespans / static_cast<double>(carried.size());
}

void TemporalRadianceCache::place_frame(const FrameScene& frame, const TcMotion& motion,
                                        const shared::IcParams& params,
                                        const shared::CameraParams& camera,
                                        const RadianceSource& diffuse) {
    const auto start = SteadyClock::now();
    const int t = frame.frame;
    RadianceCache cache(frame, options_, tables_);
    tables_ = cache.tables();  // the materials are the same every frame
    const int order = cache.order();
    order_ = order;
    TcRadianceReprojection reprojection(frame, motion, order);
    cache.set_observer(&reprojection);
    const Buffer<shared::RcQuery> queries = cache.queries(params, camera);
    // The serving records stay; an expired one is computed again in its place (with its random
    // stream) if it still serves the image and its surface stays, else dropped (the report's §5).
    std::vector<size_t> serving;
    std::vector<size_t> expired;
    cache.set_store(serving_store(t, order, &serving, &expired), next_stream_);
    std::vector<size_t> candidates;
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    std::vector<const std::vector<float>*> payloads;
    for (size_t id : expired) {
        if (!records_[id].site_moves) {
            candidates.push_back(id);
            parts.push_back(records_[id].record);
            host.push_back(records_[id].host);
            payloads.push_back(&records_[id].payload);
        }
    }
    const std::vector<uint8_t> used = cache.records_used(
        queries, radiance_store_of(options_.accuracy, order, parts, host, payloads));
    std::vector<size_t> replaced;
    std::vector<shared::RcQuery> sites;
    std::vector<unsigned> streams;
    for (size_t i = 0; i < candidates.size(); ++i) {
        if (used[i] != 0) {
            replaced.push_back(candidates[i]);
            sites.push_back(records_[candidates[i]].site);
            streams.push_back(records_[candidates[i]].stream);
        }
    }
    cache.add_records(sites, streams, diffuse);
    // New records where the image is not covered.
    cache.place(queries, params, diffuse);
    next_stream_ = cache.next_stream();

    TemporalRadianceFrameStats stats;
    std::vector<CarriedRadianceRecord> carried = reprojection.take();
    stats.reused = serving.size();
    stats.recomputed = replaced.size();
    stats.dropped = expired.size() - replaced.size();
    stats.created = carried.size() - replaced.size();
    stats.mean_new_lifespan = adopt(t, order, cache.store(), serving, std::move(carried), replaced);
    std::vector<Serving> now;
    const RecordStore& placed = cache.store();
    for (size_t i = 0; i < placed.size(); ++i) {
        const size_t id = i < serving.size() ? serving[i] : records_.size() - placed.size() + i;
        now.push_back({id, placed.records()[i], placed.host_data()[i]});
    }
    stats.records = now.size();
    stats.record_rays = cache.stats().record_rays;
    stats.placement_seconds = seconds_since(start);
    serving_.push_back(std::move(now));
    frame_stats_.push_back(stats);
}

std::unique_ptr<GlossyCache> TemporalRadianceCache::shading(const FrameScene& frame) const {
    const size_t index = static_cast<size_t>(frame.frame - first_frame_);
    if (index >= serving_.size()) {
        throw Error("temporal radiance caching: frame " + std::to_string(frame.frame) +
                    " shaded before it was placed");
    }
    const std::vector<Serving>& serving = serving_[index];
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    std::vector<std::vector<float>> values;
    values.reserve(serving.size());
    for (const Serving& s : serving) {
        const TemporalRadianceRecord& r = records_[s.record];
        const TemporalRadianceRecord* successor =
            r.successor >= 0 ? &records_[static_cast<size_t>(r.successor)] : nullptr;
        parts.push_back(s.shared);
        host.push_back(s.host);
        values.push_back(radiance_temporal_payload(r, successor, frame.frame, temporal_.gradients));
    }
    std::vector<const std::vector<float>*> payloads;
    for (const std::vector<float>& v : values) {
        payloads.push_back(&v);
    }
    return std::make_unique<TemporalRadianceShading>(
        frame, options_, tables_,
        radiance_store_of(options_.accuracy, order_, std::move(parts), std::move(host), payloads));
}

nlohmann::json TemporalRadianceCache::frame_stats(int frame) const {
    const TemporalRadianceFrameStats& s =
        frame_stats_.at(static_cast<size_t>(frame - first_frame_));
    return {{"records", s.records},         {"reused", s.reused},
            {"recomputed", s.recomputed},   {"dropped", s.dropped},
            {"created", s.created},         {"mean_new_lifespan", s.mean_new_lifespan},
            {"record_rays", s.record_rays}, {"seconds", {{"placement", s.placement_seconds}}}};
}

}  // namespace rc
