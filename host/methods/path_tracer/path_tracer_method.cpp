// `--method pt`: the reference path tracer (DESIGN.md §6.1) as a registered method.
#include <memory>

#include "methods/method.h"
#include "methods/path_tracer/path_tracer.h"
#include "shared/film.h"

namespace rc {
namespace {

const std::vector<OptionSpec> kPathTracerOptions = {
    OptionSpec{
        "--time", "", "SECONDS",
        "pt: render passes until this much time has passed, not to --spp (also -D time=SECONDS)"}
        .numbers(0.0, 1e7),
    {"--save-every-pow2", "", "",
     "pt: also write the image after 1, 2, 4, 8, ... samples per pixel (name.sppN.ext)"},
};

class PathTracerMethod final : public Method {
   public:
    PathTracerMethod(const ParsedArguments& arguments, const MethodSettings& settings)
        : settings_(settings), save_every_pow2_(arguments.has("--save-every-pow2")) {
        settings_.time = arguments.number("--time", settings.time);
    }

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
        result.image = tracer.render(options, &stats);
        result.spp = stats.spp;
        result.rays = stats.rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        result.stats = {{"spp", stats.spp}, {"rays", stats.rays}, {"seconds", stats.seconds}};
        if (!stats.devices.empty()) {
            nlohmann::json devices = nlohmann::json::array();
            for (const PathTracerDeviceShare& d : stats.devices) {
                devices.push_back({{"device", d.device},
                                   {"chunks", d.chunks},
                                   {"pixels", d.pixels},
                                   {"rays", d.rays},
                                   {"seconds", d.seconds}});
            }
            result.stats["devices"] = devices;
        }
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
    return {"pt",
            "the reference path tracer: next-event estimation, MIS, Russian roulette",
            kPathTracerOptions,
            {std::begin(kPathTracerAovs), std::end(kPathTracerAovs)},
            [](const ParsedArguments& arguments, const MethodSettings& settings) {
                return std::make_unique<PathTracerMethod>(arguments, settings);
            }};
}

}  // namespace rc
