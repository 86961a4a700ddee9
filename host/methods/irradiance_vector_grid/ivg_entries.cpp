// `--method ivg` (the grid read at the camera's hit) and `--method ivg-gather` (final gathering
// into the grid) as registered methods (DESIGN.md §6.3).
#include <memory>

#include "methods/grid/ivg_options.h"
#include "methods/irradiance_vector_grid/ivg_method.h"
#include "methods/light_samples.h"
#include "methods/method.h"
#include "methods/sample_passes.h"
#include "shared/film.h"
#include "util/timing.h"

namespace rc {
namespace {

// The options of both grid renderings: the grid's, --light-samples and (ivg-gather) the gather
// rays per camera sample.
struct GridRenderingOptions {
    IvgOptions grid;
    int light_samples = kDefaultLightSamples;
    int gather_rays = 16;
};

OptionTable<GridRenderingOptions> grid_rendering_table(bool gather) {
    using O = GridRenderingOptions;
    OptionTable<O> table;
    table.include(ivg_option_table(), &O::grid);
    add_light_samples_option(table, &O::light_samples);
    if (gather) {
        table
            .integer("--gather-rays", "N", &O::gather_rays, 1, 1 << 16,
                     "gather rays per camera sample")
            .knob(KnobDirection::kIncrease);
    }
    return table;
}

class GridRendering final : public Method {
   public:
    GridRendering(const GridRenderingOptions& options, const MethodSettings& settings,
                  int gather_rays)
        : settings_(settings),
          grid_options_(ivg_options(options.grid, settings)),
          gather_rays_(gather_rays),
          light_samples_(options.light_samples) {}

    // Without --time: the grid, then --spp camera samples over it. With --time: the grid built by
    // the first pass (one sample per pixel), each later pass's camera samples shaded over the same
    // grid (methods/sample_passes.h), at most --spp a pass.
    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks) override {
        std::unique_ptr<IrradianceVectorGrid> grid;
        if (!(settings_.time > 0.0)) {
            return render_pass(frame, hooks, {0, settings_.spp}, &grid);
        }
        FrameResult result = render_sample_passes(
            {settings_.time, settings_.spp, {}}, hooks,
            [&](const SamplePass& pass) { return render_pass(frame, hooks, pass, &grid); });
        result.stats["spp"] = result.spp;
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
    // Camera samples pass.first .. pass.first + pass.spp - 1 of every pixel shaded over *grid,
    // which is built first where empty (its figures then in the pass's stats).
    FrameResult render_pass(const FrameScene& frame, const FrameHooks& hooks,
                            const SamplePass& pass, std::unique_ptr<IrradianceVectorGrid>* grid) {
        FrameResult result;
        if (*grid == nullptr) {
            const auto start = SteadyClock::now();
            *grid = build_frame_grid(frame, grid_options_, hooks, &result);
            result.cache_seconds = seconds_since(start);
        }
        IvgMethod method(frame, **grid);
        IvgRenderOptions options;
        settings_.apply_to(options);
        options.spp = pass.spp;
        options.first_sample = pass.first;
        options.gather_rays = gather_rays_;
        options.light_samples = light_samples_;
        IvgRenderStats stats;
        result.image = method.render(options, &stats);
        result.spp = pass.spp;
        result.rays += stats.rays;
        result.nonfinite_samples = stats.nonfinite_samples;
        result.first_nonfinite_pixel = stats.first_nonfinite_pixel;
        result.stats["spp"] = pass.spp;
        result.stats["gather_rays"] = gather_rays_;
        result.stats["light_samples"] = light_samples_;
        result.stats["shading_rays"] = stats.rays;
        result.stats["seconds"] = {{"shading", stats.seconds}};
        return result;
    }

    MethodSettings settings_;
    IvgOptions grid_options_;
    int gather_rays_;
    int light_samples_;
};

std::vector<std::string> grid_aovs() { return {std::begin(kIvgAovs), std::end(kIvgAovs)}; }

MethodEntry grid_rendering_entry(std::string name, std::string summary, bool gather) {
    return method_entry<GridRenderingOptions>(
        {.name = std::move(name),
         .summary = std::move(summary),
         .aovs = grid_aovs(),
         .table = grid_rendering_table(gather),
         .finish =
             [](GridRenderingOptions& options, const ParsedArguments& arguments) {
                 finish_ivg_options(options.grid, arguments);
             },
         .check = [](const GridRenderingOptions& options,
                     const MethodSettings& settings) { ivg_options(options.grid, settings); },
         .create =
             [gather](const GridRenderingOptions& options, const MethodSettings& settings) {
                 return std::make_unique<GridRendering>(options, settings,
                                                        gather ? options.gather_rays : 0);
             }});
}

}  // namespace

MethodEntry ivg_method_entry() {
    return grid_rendering_entry(
        "ivg", "the irradiance vector grid read at the camera's hit (no gather rays)", false);
}

MethodEntry ivg_gather_method_entry() {
    return grid_rendering_entry(
        "ivg-gather", "final gathering: gather rays read the irradiance vector grid at their hits",
        true);
}

}  // namespace rc
