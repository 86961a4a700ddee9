#include "methods/glossy_method.h"

#include "methods/records/ic_stats.h"

namespace rc {

std::vector<std::string> glossy_method_aovs(const std::string& layer) {
    std::vector<std::string> aovs(std::begin(kIrradianceCacheAovs), std::end(kIrradianceCacheAovs));
    aovs.push_back("glossy-indirect");
    aovs.push_back(layer);
    return aovs;
}

FrameResult render_with_glossy_cache(const FrameScene& frame, IrradianceCacheOptions options,
                                     GlossyCache& glossy, IrradianceCacheStats* stats) {
    FrameResult result;
    options.glossy = &glossy;
    result.image = IrradianceCache(frame).render(options, stats);
    result.spp = options.spp;
    result.rays += stats->record_rays + stats->shading_rays;
    result.nonfinite_samples = stats->nonfinite_samples;
    result.first_nonfinite_pixel = stats->first_nonfinite_pixel;
    add_irradiance_cache_stats(*stats, options, &result.stats);
    return result;
}

}  // namespace rc
