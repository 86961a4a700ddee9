#include "methods/caching/glossy_mix.h"

#include <vector>

namespace rc {

void restrict_glossy_queries(Context& context, const ServedMaterials& served,
                             Buffer<shared::RcQuery>& queries) {
    if (served.empty() || queries.size() == 0) {
        return;
    }
    const std::vector<int> flags(served.begin(), served.end());
    const Buffer<int> flag_buffer(context, flags, "glossy_served_materials");
    Kernel kernel = context.kernel("caching/glossy_mix.cl", "rc_glossy_restrict");
    context.launch(kernel, queries.size(), flag_buffer, queries);
}

GlossyMix::GlossyMix(Context& context, std::vector<Member> members)
    : context_(context), members_(std::move(members)) {}

Buffer<shared::RcGlossySample> GlossyMix::glossy_samples(const shared::IcParams& params,
                                                         const shared::CameraParams& camera,
                                                         const RadianceSource& diffuse) {
    // 1. The first member's buffer: its entries, order -1 on the materials it does not serve.
    Buffer<shared::RcGlossySample> merged =
        members_.at(0).cache->glossy_samples(params, camera, diffuse);
    // 2. Each other member's served entries over it.
    for (size_t k = 1; k < members_.size(); ++k) {
        const Buffer<shared::RcGlossySample> own =
            members_[k].cache->glossy_samples(params, camera, diffuse);
        Kernel kernel = context_.kernel("caching/glossy_mix.cl", "rc_glossy_merge");
        context_.launch(kernel, merged.size(), own, merged);
    }
    return merged;
}

std::vector<FilmLayer> GlossyMix::layers() const {
    std::vector<FilmLayer> layers;
    for (const Member& member : members_) {
        for (const FilmLayer& layer : member.cache->layers()) {
            layers.push_back(layer);
        }
    }
    return layers;
}

uint64_t GlossyMix::rays() const {
    uint64_t rays = 0;
    for (const Member& member : members_) {
        rays += member.cache->rays();
    }
    return rays;
}

double GlossyMix::record_seconds() const {
    double seconds = 0.0;
    for (const Member& member : members_) {
        seconds += member.cache->record_seconds();
    }
    return seconds;
}

nlohmann::json GlossyMix::statistics() const {
    nlohmann::json stats = nlohmann::json::object();
    for (const Member& member : members_) {
        stats[member.stats_key] = member.cache->statistics();
    }
    return stats;
}

}  // namespace rc
