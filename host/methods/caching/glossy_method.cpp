#include "methods/caching/glossy_method.h"

namespace rc {

std::vector<std::string> glossy_method_aovs(const std::string& layer) {
    std::vector<std::string> aovs(std::begin(kCachePipelineAovs), std::end(kCachePipelineAovs));
    aovs.push_back("glossy-indirect");
    aovs.push_back(layer);
    return aovs;
}

FrameResult render_with_glossy_cache(const FrameScene& frame, const PipelineSettings& options,
                                     GlossyCache& glossy, double time, const FrameHooks& hooks,
                                     const RecordPassFinish& finish, PipelineStats* stats) {
    CachePipeline cache(frame, {.lobes = &glossy});
    uint64_t counted_rays = 0;  // the glossy records' rays of the passes before
    return render_record_passes(
        cache, options, time, hooks,
        [&](FrameResult& pass, const PipelineStats& ic) {
            pass.rays += glossy.rays() - counted_rays;
            counted_rays = glossy.rays();
            pass.cache_seconds += glossy.record_seconds();
            finish(pass, ic);
        },
        stats);
}

}  // namespace rc
