#include "methods/irradiance_vector_grid/ivg_method.h"

#include <limits>

#include "image/film.h"
#include "methods/scene_arguments.h"
#include "methods/shared_settings.h"
#include "scene/camera.h"
#include "shared/film.h"
#include "util/error.h"
#include "util/timing.h"

namespace rc {

const char* const kIvgAovs[6] = {"beauty", "direct", "indirect", "albedo", "normal", "grid"};

namespace {

// The grid's parameters with this render's camera samples and gather rays.
class RenderGrid : public KernelArgumentGroup {
   public:
    RenderGrid(const IrradianceVectorGrid& grid, const IvgRenderOptions& options) : grid_(grid) {
        params_ = grid.params();
        params_.gather_rays = options.gather_rays;
        params_.light_samples = options.light_samples;
        params_.camera_spp = options.spp;
        params_.first_sample = options.first_sample;
        set_kernel_seed(options.seed, &params_);
    }
    unsigned set_kernel_args(Kernel& kernel, unsigned first) const override {
        const unsigned count = grid_.set_kernel_args(kernel, first);
        kernel.set_arg(first, sizeof params_, &params_);
        return count;
    }

   private:
    const IrradianceVectorGrid& grid_;
    shared::IvgParams params_{};
};

}  // namespace

IvgMethod::IvgMethod(const FrameScene& frame, const IrradianceVectorGrid& grid)
    : FrameBound(frame),
      grid_(grid),
      shade_kernel_(
          frame.context.kernel("irradiance_vector_grid/irradiance_vector_grid.cl", "ivg_shade")) {}

Image IvgMethod::render(const IvgRenderOptions& options, IvgRenderStats* stats) {
    const int width = options.width > 0 ? options.width : scene_.camera.width;
    const int height = options.height > 0 ? options.height : scene_.camera.height;
    const size_t pixels = static_cast<size_t>(width) * height;
    if (options.spp < 1) {
        throw Error("the irradiance vector grid needs at least one camera sample per pixel",
                    kExitUsage);
    }
    if (options.first_sample < 0 ||
        static_cast<int64_t>(options.first_sample) + options.spp > (int64_t{1} << 31) - 1) {
        throw Error("irradiance vector grid: camera sample indices beyond 2^31", kExitUsage);
    }
    if (options.gather_rays < 0) {
        throw Error("--gather-rays must not be negative", kExitUsage);
    }
    if (options.light_samples < 1) {
        throw Error("--light-samples must be at least 1", kExitUsage);
    }
    if (pixels > std::numeric_limits<uint32_t>::max()) {
        throw Error("irradiance vector grid: width x height exceeds 2^32 pixels", kExitUsage);
    }
    const auto start = SteadyClock::now();
    const shared::CameraParams camera = camera_params(scene_.camera, width, height);
    const SceneArguments scene(bvh_, device_scene_);
    const RenderGrid grid(grid_, options);
    Buffer<shared::float4> film(context_, pixels * RC_CACHED_FILM_SLOTS, "ivg_film");
    Buffer<unsigned> counters(context_, 3, "ivg_counters");
    counters.upload({0u, 0u, 0xffffffffu});
    context_.launch(shade_kernel_, pixels, grid, camera, scene, film, counters);
    const std::vector<shared::float4> sums = film.download();
    const std::vector<unsigned> c = counters.download();

    Image image = unpack_film(sums, RC_CACHED_FILM_SLOTS, width, height,
                              {{"beauty", RC_CACHED_FILM_BEAUTY},
                               {"direct", RC_CACHED_FILM_DIRECT},
                               {"indirect", RC_CACHED_FILM_INDIRECT},
                               {"albedo", RC_CACHED_FILM_ALBEDO},
                               {"normal", RC_CACHED_FILM_NORMAL},
                               {"grid", RC_CACHED_FILM_LAYER}});
    if (stats != nullptr) {
        stats->rays = c[0];
        stats->nonfinite_samples = c[1];
        stats->first_nonfinite_pixel = c[1] > 0 ? static_cast<int64_t>(c[2]) : -1;
        stats->seconds = seconds_since(start);
    }
    return image;
}

}  // namespace rc
