#include "methods/glossy_method.h"

namespace rc {

std::vector<std::string> glossy_method_aovs(const std::string& layer) {
    std::vector<std::string> aovs(std::begin(kIrradianceCacheAovs), std::end(kIrradianceCacheAovs));
    aovs.push_back("glossy-indirect");
    aovs.push_back(layer);
    return aovs;
}

FrameResult render_with_glossy_cache(const FrameScene& frame, IrradianceCacheOptions options,
                                     GlossyCache& glossy, double time, const FrameHooks& hooks,
                                     const RecordPassFinish& finish, IrradianceCacheStats* stats) {
    options.glossy = &glossy;
    IrradianceCache cache(frame);
    uint64_t counted_rays = 0;  // the glossy records' rays of the passes before
    return render_record_passes(
        cache, options, time, hooks,
        [&](FrameResult& pass, const IrradianceCacheStats& ic) {
            pass.rays += glossy.rays() - counted_rays;
            counted_rays = glossy.rays();
            pass.cache_seconds += glossy.record_seconds();
            finish(pass, ic);
        },
        stats);
}

}  // namespace rc
