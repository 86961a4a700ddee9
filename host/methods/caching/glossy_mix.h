// Several glossy caches serving the materials of one scene in one render by irradiance caching
// (`--method ic --glossy`, methods/caching/glossy_spec.h): each cache serves its set of materials
// (its camera samples on the others are left alone, so it places no records for them), and the mix
// merges their glossy buffers into the one the render pass reads, each camera sample's entry from
// the cache that serves its material (kernels/caching/glossy_mix.cl). Deterministic: the merge
// writes each entry from at most one cache.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "device/buffer.h"
#include "device/context.h"
#include "methods/caching/glossy_cache.h"

namespace rc {

// Sets order -1 (path tracing) on the queries of materials `served` does not mark; nothing when
// it is empty (every material served).
void restrict_glossy_queries(Context& context, const ServedMaterials& served,
                             Buffer<shared::RcQuery>& queries);

class GlossyMix final : public GlossyCache {
   public:
    struct Member {
        std::string stats_key;  // its statistics' key (GlossyCacheEntry::stats_key)
        std::unique_ptr<GlossyCache> cache;
    };

    // The members serve disjoint sets of materials; their layers and statistics come in order.
    GlossyMix(Context& context, std::vector<Member> members);

    // Every member's glossy buffer in turn, merged into the first's.
    Buffer<shared::RcGlossySample> glossy_samples(const shared::IcParams& params,
                                                  const shared::CameraParams& camera,
                                                  const RadianceSource& diffuse) override;
    std::vector<FilmLayer> layers() const override;
    uint64_t rays() const override;
    double record_seconds() const override;
    // {stats_key: the member's statistics} per member.
    nlohmann::json statistics() const override;

   private:
    Context& context_;
    std::vector<Member> members_;
};

}  // namespace rc
