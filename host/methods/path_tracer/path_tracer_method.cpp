// `--method pt`: the reference path tracer (DESIGN.md §6.1) as a registered method.
#include <memory>

#include "methods/device_shares.h"
#include "methods/method.h"
#include "methods/path_tracer/path_tracer.h"
#include "shared/film.h"

namespace rc {
namespace {

// pt's own options (--time is the render's, MethodSettings::time).
struct PathTracerMethodOptions {
    bool save_every_pow2 = false;
};

OptionTable<PathTracerMethodOptions> path_tracer_option_table() {
    using O = PathTracerMethodOptions;
    OptionTable<O> table;
    table.flag("--save-every-pow2", &O::save_every_pow2,
               "also write the image after 1, 2, 4, 8, ... samples per pixel (name.sppN.ext)");
    return table;
}

class PathTracerMethod final : public Method {
   public:
    PathTracerMethod(const PathTracerMethodOptions& options, const MethodSettings& settings)
        : settings_(settings), save_every_pow2_(options.save_every_pow2) {}

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        PathTracer tracer(frame);
        PathTracerOptions options;
        settings_.apply_to(options);
        options.time_limit = settings_.time;
        if (save_every_pow2_) {
            options.on_power_of_two = hooks.intermediate;
        }
        options.on_progress = [&](double fraction, int spp) {
            hooks.progress(fraction, std::to_string(spp) + " spp");
        };
        PathTracerStats stats;
        FrameResult result;
        if (settings_.write_sums) {
            options.sums = &result.sums;
        }
        result.image = tracer.render(options, &stats);
        result.spp = stats.spp;
        result.rays = stats.rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        result.stats = {{"spp", stats.spp}, {"rays", stats.rays}, {"seconds", stats.seconds}};
        add_device_shares(stats.devices, &result.stats, [](const PathTracerDeviceShare& d) {
            return nlohmann::json{{"device", d.device},
                                  {"chunks", d.chunks},
                                  {"pixels", d.pixels},
                                  {"rays", d.rays},
                                  {"seconds", d.seconds}};
        });
        return result;
    }

    bool splits_across_devices() const override { return true; }

    std::vector<ProgramRequest> programs() const override {
        return {{"path_tracer/path_tracer.cl", ""}};
    }

    DeviceMemoryNeed device_memory_need(const Scene& scene,
                                        const DeviceInfo& device) const override {
        DeviceMemoryNeed need;
        const int width = settings_.width > 0 ? settings_.width : scene.camera.width;
        const int height = settings_.height > 0 ? settings_.height : scene.camera.height;
        check_film_size(width, height, device);
        const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
        need.add("film", buffer_bytes(pixels * RC_PT_FILM_SLOTS, sizeof(shared::float4)));
        need.add("counters", buffer_bytes(3, sizeof(unsigned)));
        return need;
    }

   private:
    MethodSettings settings_;
    bool save_every_pow2_;
};

}  // namespace

MethodEntry path_tracer_method_entry() {
    return method_entry<PathTracerMethodOptions>(
        {.name = "pt",
         .summary = "the reference path tracer: next-event estimation, MIS, Russian roulette",
         .aovs = {std::begin(kPathTracerAovs), std::end(kPathTracerAovs)},
         .table = path_tracer_option_table(),
         .finish = nullptr,
         .check = nullptr,
         .create = [](const PathTracerMethodOptions& options, const MethodSettings& settings) {
             return std::make_unique<PathTracerMethod>(options, settings);
         }});
}

}  // namespace rc
