#include "methods/glossy_method.h"

#include "methods/irradiance_cache/ic_options.h"
#include "methods/irradiance_cache/ic_stats.h"

namespace rc {

std::vector<OptionSpec> glossy_method_ic_option_specs() {
    std::vector<OptionSpec> specs;
    for (OptionSpec& spec : irradiance_cache_option_specs()) {
        const bool shared = spec.name == "--accuracy" ||
                            (spec.name.rfind("--ic-", 0) == 0 && spec.name != "--ic-ivg") ||
                            spec.name == "--light-samples" || spec.name == "--cache-in" ||
                            spec.name == "--cache-out";
        if (shared) {
            specs.push_back(std::move(spec));
        }
    }
    return specs;
}

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
