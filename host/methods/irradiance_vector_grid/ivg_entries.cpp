// `--method ivg` (the grid read at the camera's hit) and `--method ivg-gather` (final gathering
// into the grid) as registered methods (DESIGN.md §6.3).
#include <memory>

#include "methods/irradiance_vector_grid/ivg_method.h"
#include "methods/irradiance_vector_grid/ivg_options.h"
#include "methods/light_samples.h"
#include "methods/method.h"
#include "shared/film.h"

namespace rc {
namespace {

constexpr int kDefaultGatherRays = 16;

const OptionSpec kGatherRaysOption =
    OptionSpec{"--gather-rays", "", "N", "ivg-gather: gather rays per camera sample (default 16)"}
        .integers(1, 1 << 16);

class GridRendering final : public Method {
   public:
    GridRendering(const ParsedArguments& arguments, const MethodSettings& settings, int gather_rays)
        : settings_(settings),
          grid_options_(ivg_options(arguments, settings)),
          gather_rays_(gather_rays),
          light_samples_(light_samples(arguments)) {}

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        FrameResult result;
        const std::unique_ptr<IrradianceVectorGrid> grid =
            build_frame_grid(frame, grid_options_, hooks, &result);
        IvgMethod method(frame, *grid);
        IvgRenderOptions options;
        settings_.apply_to(options);
        options.gather_rays = gather_rays_;
        options.light_samples = light_samples_;
        IvgRenderStats stats;
        result.image = method.render(options, &stats);
        result.spp = settings_.spp;
        result.rays += stats.rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        result.stats["spp"] = settings_.spp;
        result.stats["gather_rays"] = gather_rays_;
        result.stats["light_samples"] = light_samples_;
        result.stats["shading_rays"] = stats.rays;
        result.stats["seconds"] = {{"shading", stats.seconds}};
        return result;
    }

    std::vector<ProgramRequest> programs() const override {
        return {{"irradiance_vector_grid/irradiance_vector_grid.cl", ""}};
    }

    // The grid's photons are shared among the devices (ivg_photon_split.cpp); the shading pass
    // runs on the first.
    bool splits_across_devices() const override { return true; }

    DeviceMemoryNeed device_memory_need(const Scene& scene, const DeviceInfo&) const override {
        const IvgDeviceNeed grid = ivg_device_need(grid_options_, scene);
        DeviceMemoryNeed shading = grid.built;
        const size_t pixels = image_pixels(settings_.width, settings_.height, scene);
        shading.add("film", buffer_bytes(pixels * RC_CACHED_FILM_SLOTS, sizeof(shared::float4)));
        shading.add("counters", buffer_bytes(3, sizeof(unsigned)));
        return peak_of(grid.building, shading);
    }

   private:
    MethodSettings settings_;
    IvgOptions grid_options_;
    int gather_rays_;
    int light_samples_;
};

std::vector<std::string> grid_aovs() { return {std::begin(kIvgAovs), std::end(kIvgAovs)}; }

// The options of both grid renderings: the grid's and --light-samples.
std::vector<OptionSpec> grid_rendering_options() {
    std::vector<OptionSpec> options = ivg_option_specs();
    options.push_back(kLightSamplesOption);
    return options;
}

}  // namespace

MethodEntry ivg_method_entry() {
    return {"ivg", "the irradiance vector grid read at the camera's hit (no gather rays)",
            grid_rendering_options(), grid_aovs(),
            [](const ParsedArguments& arguments, const MethodSettings& settings) {
                return std::make_unique<GridRendering>(arguments, settings, 0);
            }};
}

MethodEntry ivg_gather_method_entry() {
    std::vector<OptionSpec> options = grid_rendering_options();
    options.push_back(kGatherRaysOption);
    return {"ivg-gather",
            "final gathering: gather rays read the irradiance vector grid at their hits", options,
            grid_aovs(), [](const ParsedArguments& arguments, const MethodSettings& settings) {
                const int gather_rays =
                    static_cast<int>(arguments.integer("--gather-rays", kDefaultGatherRays));
                return std::make_unique<GridRendering>(arguments, settings, gather_rays);
            }};
}

}  // namespace rc
