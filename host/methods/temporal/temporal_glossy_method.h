// What the glossy caches' methods (`rc`, `sdrc`) share to render an animation with --temporal
// (docs/temporal-caching.md): the rules of their temporal options, and temporal irradiance
// caching driving the glossy cache's records across frames (TemporalGlossyRecords).
#pragma once

#include <memory>
#include <string>

#include "methods/caching/cache_pipeline.h"
#include "methods/method.h"
#include "methods/temporal/temporal_cache.h"
#include "methods/temporal/temporal_glossy.h"
#include "methods/temporal/temporal_options.h"
#include "util/cli.h"

namespace rc {

// Error (exit status 2) naming the option: the --temporal-* options without --temporal; with
// it, lifespans by departure (a glossy record's lifespan is by change) and the method's cache
// files (`cache_files`: any given; `cache_options`: their names). Records in `options` whether
// --temporal-max-frames was given (check_temporal_options).
void check_glossy_temporal_options(TemporalOptions& options, const ParsedArguments& arguments,
                                   bool cache_files, const std::string& cache_options);

// The last frame of the run `settings` describe.
int temporal_last_frame(const MethodSettings& settings);

// Temporal irradiance caching with `glossy`'s records serving the specular lobes.
class TemporalGlossyRender {
   public:
    TemporalGlossyRender(std::unique_ptr<TemporalGlossyRecords> glossy, const PipelineSettings& ic,
                         const TemporalOptions& temporal, const MethodSettings& settings);

    // One frame (in order; on one device), its records' counts logged, the glossy records
    // named `records` ("radiance", "SDRC").
    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks,
                             const std::string& records);

   private:
    std::unique_ptr<TemporalGlossyRecords> glossy_;
    TemporalIrradianceCache cache_;
};

// With --temporal (`temporal`), the temporal render of the glossy records `Records`, made from the
// glossy cache's options `glossy` (constructed as Records(glossy, temporal, first frame, last
// frame)); else null.
template <class Records, class GlossyOptions>
std::unique_ptr<TemporalGlossyRender> temporal_glossy_render(const GlossyOptions& glossy,
                                                             const PipelineSettings& ic,
                                                             const TemporalOptions& temporal,
                                                             const MethodSettings& settings) {
    if (!temporal.enabled) {
        return nullptr;
    }
    return std::make_unique<TemporalGlossyRender>(
        std::make_unique<Records>(glossy, temporal, settings.first_frame,
                                  temporal_last_frame(settings)),
        ic, temporal, settings);
}

}  // namespace rc
