#include "methods/sdrc/temporal_sdrc_cache.h"

#include <string>
#include <utility>

#include "methods/sdrc/tc_sdrc_reprojection.h"
#include "util/error.h"
#include "util/timing.h"

namespace rc {
namespace {

// The glossy cache of one frame's shading: SDRC's queries and interpolation over given records
// (their placement already covers the frame's camera samples: place() adds none).
class TemporalSdrcShading final : public TemporalShadingCache<SdrcCache> {
   public:
    TemporalSdrcShading(const FrameScene& frame, const SdrcOptions& options, RecordStore store,
                        std::vector<shared::RcQuery> sites, std::vector<LTree> trees)
        : TemporalShadingCache(frame, options) {
        cache_.set_records(std::move(store), std::move(sites), std::move(trees), 0);
    }

    Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                  const shared::CameraParams& camera,
                                                  const RadianceSource& diffuse) override {
        SdrcQueries q = cache_.queries(params, camera);
        cache_.place(q.queries, params, diffuse);
        cache_.interpolate(q, params, diffuse);
        return std::move(q.glossy);
    }
};

}  // namespace

TemporalSdrcCache::TemporalSdrcCache(SdrcOptions options, TemporalOptions temporal, int first_frame,
                                     int last_frame)
    : TemporalGlossySetRecords(temporal, first_frame, last_frame), options_(std::move(options)) {}

LTree TemporalSdrcCache::tree_at(size_t id, int frame) const {
    const TemporalGlossyRecord& r = set_.records()[id];
    LTree tree;
    tree.tree = nodes_[id];
    const std::vector<float> payload = set_.payload_at(id, frame);
    if (payload != r.payload) {  // the samples' radiance moved by the temporal gradients (§4.4)
        const size_t n = tree.tree.size();
        for (size_t k = 0; k < n; ++k) {
            if ((tree.tree[k].position & RC_LTREE_EMPTY) == 0u) {
                tree.tree[k].radiance =
                    shared::rc_rgbe_encode(payload[k], payload[n + k], payload[2 * n + k]);
            }
        }
    }
    build_ltree(&tree.tree);
    return tree;
}

TemporalSdrcCache::Records TemporalSdrcCache::records_of(const std::vector<size_t>& ids,
                                                         std::vector<shared::Record> parts,
                                                         std::vector<RecordHostData> host,
                                                         int frame) const {
    Records records{RecordStore(options_.accuracy, 0), {}, {}};
    records.store.restore(std::move(parts), std::move(host), {});
    for (size_t id : ids) {
        records.sites.push_back(set_.records()[id].site);
        records.trees.push_back(frame >= 0 ? tree_at(id, frame) : LTree{});
    }
    return records;
}

void TemporalSdrcCache::place_frame(const FrameScene& frame, const TcMotion& motion,
                                    const shared::IcParams& params,
                                    const shared::CameraParams& camera,
                                    const RadianceSource& diffuse) {
    const auto start = SteadyClock::now();
    const int t = frame.frame;
    SdrcCache cache(frame, options_);
    TcSdrcReprojection reprojection(frame, motion);
    cache.set_observer(&reprojection);
    const SdrcQueries queries = cache.queries(params, camera);
    // The serving records stay; an expired one is computed again in its place (with its random
    // stream) if it still serves the image and its surface stays, else dropped (the report's §5).
    std::vector<size_t> serving;
    std::vector<size_t> expired;
    set_.select(t, &serving, &expired);
    const auto parts_of = [&](const std::vector<size_t>& ids, std::vector<shared::Record>* parts,
                              std::vector<RecordHostData>* host) {
        for (size_t id : ids) {
            parts->push_back(set_.records()[id].record);
            host->push_back(set_.records()[id].host);
        }
    };
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    parts_of(serving, &parts, &host);
    Records now = records_of(serving, std::move(parts), std::move(host), -1);
    cache.set_records(std::move(now.store), std::move(now.sites), std::move(now.trees),
                      set_.next_stream());
    const std::vector<size_t> candidates = set_.staying(expired);
    parts.clear();
    host.clear();
    parts_of(candidates, &parts, &host);
    const std::vector<uint8_t> used = cache.records_used(
        queries.queries, records_of(candidates, std::move(parts), std::move(host), -1).store);
    const TemporalGlossySet::Replacements replaced = set_.replacements(candidates, used);
    cache.add_records(replaced.sites, replaced.streams, params, diffuse);
    // New records where the image is not covered.
    cache.place(queries.queries, params, diffuse);
    set_.set_next_stream(cache.next_stream());

    std::vector<CarriedSdrcRecord> observed = reprojection.take();
    std::vector<CarriedGlossyRecord> carried;
    std::vector<std::vector<float>> payloads;
    for (CarriedSdrcRecord& r : observed) {
        carried.push_back(std::move(r.carried));
        payloads.push_back(std::move(r.payload));
        nodes_.push_back(std::move(r.nodes));
    }
    const size_t samples = static_cast<size_t>(sdrc_record_samples(options_, params.camera_spp));
    TemporalGlossyFrameStats& stats =
        set_.adopt(t, cache.store(), serving, expired.size(), std::move(carried),
                   std::move(payloads), replaced.records, samples);
    stats.record_rays = cache.stats().record_rays;  // the cells' rays included
    stats.placement_seconds = seconds_since(start);
}

std::unique_ptr<GlossyCache> TemporalSdrcCache::shading(const FrameScene& frame) const {
    const std::vector<TemporalGlossySet::Serving>& serving = set_.serving(frame.frame);
    std::vector<size_t> ids;
    std::vector<shared::Record> parts;
    std::vector<RecordHostData> host;
    for (const TemporalGlossySet::Serving& s : serving) {
        ids.push_back(s.record);
        parts.push_back(s.shared);
        host.push_back(s.host);
    }
    Records records = records_of(ids, std::move(parts), std::move(host), frame.frame);
    return std::make_unique<TemporalSdrcShading>(frame, options_, std::move(records.store),
                                                 std::move(records.sites),
                                                 std::move(records.trees));
}

}  // namespace rc
