#include "methods/caching/record_passes.h"

#include "methods/caching/pipeline_stats.h"
#include "methods/sample_passes.h"

namespace rc {

FrameResult render_record_passes(CachePipeline& cache, const PipelineSettings& options, double time,
                                 const FrameHooks& hooks, const RecordPassFinish& finish,
                                 PipelineStats* last) {
    const auto pass = [&](const SamplePass& samples) {
        PipelineSettings pass_options = options;
        pass_options.first_sample = samples.first;
        pass_options.spp = samples.spp;
        PipelineStats stats;
        FrameResult result;
        result.image = samples.first == 0 ? cache.render(pass_options, &stats)
                                          : cache.render_more(pass_options, &stats);
        result.spp = samples.spp;
        result.rays = stats.record_rays + stats.shading_rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        result.cache_seconds =
            stats.placement_seconds + stats.record_seconds + stats.insertion_seconds;
        add_irradiance_cache_stats(stats, pass_options, &result.stats);
        if (finish) {
            finish(result, stats);
        }
        if (last != nullptr) {
            *last = stats;
        }
        return result;
    };
    if (time > 0.0) {
        return render_sample_passes({time, options.spp, {}}, hooks, pass);
    }
    return pass({0, options.spp});
}

}  // namespace rc
