// `--method ic`: irradiance caching (DESIGN.md §6.2) as a registered method: its options, its
// statistics per frame, and (with --ic-ivg) the irradiance vector grid as the radiance its
// hemisphere rays read beyond their hits.
#include <memory>

#include "methods/irradiance_cache/ic_options.h"
#include "methods/irradiance_cache/ic_stats.h"
#include "methods/irradiance_cache/irradiance_cache.h"
#include "methods/irradiance_vector_grid/ivg_options.h"
#include "methods/light_samples.h"
#include "methods/method.h"
#include "util/log.h"

namespace rc {
namespace {

class IrradianceCaching final : public Method {
   public:
    IrradianceCaching(const ParsedArguments& arguments, const MethodSettings& settings)
        : options_(parse_irradiance_cache_options(arguments, settings)),
          with_grid_(arguments.has("--ic-ivg")) {
        if (with_grid_) {
            grid_options_ = ivg_options(arguments, settings);
        } else {
            refuse_ivg_options(arguments,
                               "applies to --method ivg, ivg-gather, or ic with --ic-ivg");
        }
    }

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        FrameResult result;
        std::unique_ptr<IrradianceVectorGrid> grid;
        if (with_grid_) {
            grid = build_frame_grid(frame, grid_options_, hooks, &result);
        }
        IrradianceCache cache(frame);
        IrradianceCacheOptions options = options_;
        options.source = grid.get();
        IrradianceCacheStats stats;
        result.image = cache.render(options, &stats);
        result.spp = options.spp;
        result.rays += stats.record_rays + stats.shading_rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        add_irradiance_cache_stats(stats, options_, &result.stats);
        log_note(std::to_string(stats.records) + " irradiance records");
        return result;
    }

   private:
    IrradianceCacheOptions options_;
    bool with_grid_;
    IvgOptions grid_options_;
};

}  // namespace

MethodEntry irradiance_cache_method_entry() {
    return {"ic",
            "irradiance caching: records with gradients, neighbor clamping, interpolated",
            irradiance_cache_option_specs(),
            {std::begin(kIrradianceCacheAovs), std::end(kIrradianceCacheAovs)},
            [](const ParsedArguments& arguments, const MethodSettings& settings) {
                return std::make_unique<IrradianceCaching>(arguments, settings);
            }};
}

}  // namespace rc
