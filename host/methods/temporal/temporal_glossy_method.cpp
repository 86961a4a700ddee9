#include "methods/temporal/temporal_glossy_method.h"

#include <algorithm>
#include <utility>

#include "util/error.h"
#include "util/log.h"

namespace rc {

void check_glossy_temporal_options(TemporalOptions& options, const ParsedArguments& arguments,
                                   bool cache_files, const std::string& cache_options) {
    check_temporal_options(options, arguments);
    if (!options.enabled) {
        return;
    }
    if (options.lifespan == TemporalLifespan::kDeparture) {
        throw Error(
            "--temporal-lifespan departure: --method ic only (rc's and sdrc's glossy records' "
            "lifespans are by change)",
            kExitUsage);
    }
    refuse_cache_files_with_temporal(cache_files, cache_options);
}

int temporal_last_frame(const MethodSettings& settings) {
    return static_cast<int>(static_cast<long long>(settings.first_frame) +
                            std::max(settings.frame_count, 1) - 1);
}

TemporalGlossyRender::TemporalGlossyRender(std::unique_ptr<TemporalGlossyRecords> glossy,
                                           const PipelineSettings& ic,
                                           const TemporalOptions& temporal,
                                           const MethodSettings& settings)
    : glossy_(std::move(glossy)), cache_(ic, temporal, settings.first_frame, settings.frame_count) {
    cache_.set_glossy(glossy_.get());
}

FrameResult TemporalGlossyRender::render_frame(const FrameScene& frame, const FrameHooks& hooks,
                                               const std::string& records) {
    refuse_temporal_on_several_devices(frame_devices(frame));
    FrameResult result = cache_.render_frame(frame, hooks);
    const nlohmann::json& t = result.stats["temporal"];
    const nlohmann::json& r = t["radiance"];
    log_note(t["records"].dump() + " irradiance records, " + r["records"].dump() + " " + records +
             " records (" + r["created"].dump() + " new, " + r["recomputed"].dump() +
             " recomputed, " + r["reused"].dump() + " reused, " + r["dropped"].dump() +
             " dropped)");
    return result;
}

}  // namespace rc
