#include "methods/caching/glossy_plan.h"

#include <algorithm>

#include "methods/caching/glossy_caches.h"

namespace rc {

void check_glossy_spec(const GlossySpec& spec, const Scene& scene) {
    resolve_glossy_spec(spec, scene.materials);
}

std::unique_ptr<GlossyMix> make_glossy_mix(const FrameScene& frame, const PipelineSettings& ic,
                                           const GlossySpec& spec) {
    const std::vector<std::string> caches = spec.caches();
    if (caches.empty()) {
        return nullptr;
    }
    const std::vector<std::string> servers = resolve_glossy_spec(spec, frame.scene.materials);
    std::vector<GlossyMix::Member> members;
    for (const std::string& name : caches) {
        const GlossyCacheEntry& entry = *find_glossy_cache(name);
        ServedMaterials served;  // empty: every material (no material named)
        if (!spec.uniform()) {
            for (const std::string& server : servers) {
                served.push_back(server == name ? 1 : 0);
            }
        }
        members.push_back({entry.stats_key, entry.create(frame, ic, served)});
    }
    return std::make_unique<GlossyMix>(frame.context, std::move(members));
}

std::vector<ProgramRequest> glossy_programs(const GlossySpec& spec) {
    std::vector<ProgramRequest> programs;
    const auto add = [&](const ProgramRequest& request) {
        const bool listed = std::any_of(programs.begin(), programs.end(), [&](const auto& p) {
            return p.entry == request.entry && p.options == request.options;
        });
        if (!listed) {
            programs.push_back(request);
        }
    };
    const std::vector<std::string> caches = spec.caches();
    for (const std::string& name : caches) {
        for (const ProgramRequest& request : find_glossy_cache(name)->programs) {
            add(request);
        }
    }
    // Restricting a cache to its materials, merging several caches' buffers.
    if (!caches.empty() && (!spec.uniform() || caches.size() > 1)) {
        add({"caching/glossy_mix.cl", ""});
    }
    return programs;
}

GlossySampleBytes glossy_sample_bytes(const GlossySpec& spec, std::string* excludes) {
    GlossySampleBytes bytes;
    const std::vector<std::string> caches = spec.caches();
    for (const std::string& name : caches) {
        const GlossyCacheEntry& entry = *find_glossy_cache(name);
        bytes.queries = std::max(bytes.queries, entry.bytes.queries);
        bytes.glossy = std::max(bytes.glossy, entry.bytes.glossy);
        bytes.fixed = std::max(bytes.fixed, entry.bytes.fixed);
        *excludes += ", " + entry.excludes;
    }
    // The merged buffer beside a later cache's queries and glossy samples.
    if (caches.size() > 1) {
        bytes.queries += (caches.size() - 1) * sizeof(shared::RcGlossySample);
    }
    return bytes;
}

}  // namespace rc
