#include "methods/radiance_cache/temporal_radiance_cache.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "methods/radiance_cache/radiance_records.h"
#include "methods/radiance_cache/tc_radiance_reprojection.h"
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
class TemporalRadianceShading final : public TemporalShadingCache<RadianceCache> {
   public:
    TemporalRadianceShading(const FrameScene& frame, const RadianceCacheOptions& options,
                            std::shared_ptr<const BrdfTables> tables, RecordStore store)
        : TemporalShadingCache(frame, options, std::move(tables)) {
        cache_.set_store(std::move(store), 0);
    }

    Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                  const shared::CameraParams& camera,
                                                  const RadianceSource&) override {
        return cache_.splat(cache_.queries(params, camera));
    }
};

}  // namespace

TemporalRadianceCache::TemporalRadianceCache(RadianceCacheOptions options, TemporalOptions temporal,
                                             int first_frame, int last_frame)
    : TemporalGlossySetRecords(temporal, first_frame, last_frame), options_(std::move(options)) {}

RecordStore TemporalRadianceCache::serving_store(int frame, int order, std::vector<size_t>* serving,
                                                 std::vector<size_t>* expired) const {
    set_.select(frame, serving, expired);
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    std::vector<const std::vector<float>*> payloads;
    for (size_t id : *serving) {
        const TemporalRadianceRecord& r = set_.records()[id];
        parts.push_back(r.record);
        host.push_back(r.host);
        payloads.push_back(&r.payload);
    }
    return radiance_store_of(options_.accuracy, order, std::move(parts), std::move(host), payloads);
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
    cache.set_store(serving_store(t, order, &serving, &expired), set_.next_stream());
    const std::vector<size_t> candidates = set_.staying(expired);
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    std::vector<const std::vector<float>*> payloads;
    for (size_t id : candidates) {
        parts.push_back(set_.records()[id].record);
        host.push_back(set_.records()[id].host);
        payloads.push_back(&set_.records()[id].payload);
    }
    const std::vector<uint8_t> used = cache.records_used(
        queries, radiance_store_of(options_.accuracy, order, parts, host, payloads));
    const TemporalGlossySet::Replacements replaced = set_.replacements(candidates, used);
    cache.add_records(replaced.sites, replaced.streams, diffuse);
    // New records where the image is not covered.
    cache.place(queries, params, diffuse);
    set_.set_next_stream(cache.next_stream());

    const RecordStore& placed = cache.store();
    std::vector<CarriedRadianceRecord> carried = reprojection.take();
    const size_t floats = radiance_payload_floats(order);
    std::vector<std::vector<float>> computed;
    for (size_t i = serving.size(); i < placed.size(); ++i) {
        const auto* data = reinterpret_cast<const float*>(placed.payload_data(i));
        computed.emplace_back(data, data + floats);
    }
    TemporalGlossyFrameStats& stats =
        set_.adopt(t, placed, serving, expired.size(), std::move(carried), std::move(computed),
                   replaced.records, static_cast<size_t>(order) * order);
    stats.record_rays = cache.stats().record_rays;
    stats.placement_seconds = seconds_since(start);
}

std::unique_ptr<GlossyCache> TemporalRadianceCache::shading(const FrameScene& frame) const {
    const std::vector<TemporalGlossySet::Serving>& serving = set_.serving(frame.frame);
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    std::vector<std::vector<float>> values;
    values.reserve(serving.size());
    for (const TemporalGlossySet::Serving& s : serving) {
        parts.push_back(s.shared);
        host.push_back(s.host);
        values.push_back(set_.payload_at(s.record, frame.frame));
    }
    std::vector<const std::vector<float>*> payloads;
    for (const std::vector<float>& v : values) {
        payloads.push_back(&v);
    }
    return std::make_unique<TemporalRadianceShading>(
        frame, options_, tables_,
        radiance_store_of(options_.accuracy, order_, std::move(parts), std::move(host), payloads));
}

}  // namespace rc
