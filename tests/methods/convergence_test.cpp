// Convergence of the caching methods with their quality knobs: on the Cornell
// box, each method's indirect light moves towards the path-traced reference as a knob tightens —
// irradiance caching's accuracy, hemisphere rays and record spacing; the irradiance vector
// grid's photons and grid resolution. The oracle is the shipped path-traced reference, box
// filtered from 512² to the tests' 64² (the camera's pixel filter is a box: a 64² pixel's
// expected value is the mean of the 8 x 8 reference pixels it covers).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "image/image_error.h"
#include "image_options.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "methods/irradiance_vector_grid/ivg_method.h"
#include "test_support.h"

namespace rc {
namespace {

constexpr int kSize = 64;

const Image& reference_indirect() {
    static const Image reference = test::cornell_reference("indirect", kSize);
    return reference;
}

double indirect_relmse(const Image& image, const char* what) {
    const ImageError e = image_error(select_layers(image, {"indirect"}), reference_indirect());
    std::printf("%-40s indirect relMSE %.3g\n", what, e.relmse);
    return e.relmse;
}

// Irradiance caching at 64², 4 camera samples per pixel (the all-diffuse box's indirect layer
// carries no camera noise: every camera sample reads the cache).
double ic_error(float accuracy, int rays, float min_spacing_pixels, const char* what) {
    test::DeviceFrame device(test::load_cornell_box());
    CachePipeline cache(device.frame());
    auto options = test::image_options<PipelineSettings>(kSize, kSize, 4, 21);
    options.accuracy = accuracy;
    options.rays = rays;
    options.min_spacing = {min_spacing_pixels, false};
    options.max_spacing = {std::max(64.0f, min_spacing_pixels), false};
    options.bounces = 1;  // hemisphere rays path traced beyond their hits: the knobs alone
    options.records_overlay = false;
    return indirect_relmse(cache.render(options), what);
}

// Each of the cache's knobs lowers the error on its own from a loose setting, and all three
// tightened together end at a small fraction of the loose setting's error. Loose: a = 0.6, 128
// rays, R_min = 16 pixels.
TEST(Convergence, IrradianceCachingErrorFallsAsEveryKnobTightens) {
    const double loose = ic_error(0.6f, 128, 16.0f, "ic loose (a 0.6, 128 rays, 16px)");
    const double accuracy = ic_error(0.2f, 128, 16.0f, "ic accuracy 0.2");
    const double rays = ic_error(0.6f, 1024, 16.0f, "ic 1024 rays");
    const double spacing = ic_error(0.6f, 128, 2.0f, "ic R_min 2px");
    const double tight = ic_error(0.2f, 1024, 2.0f, "ic tight (a 0.2, 1024 rays, 2px)");
    EXPECT_LT(accuracy, 0.8 * loose);
    EXPECT_LT(rays, 0.8 * loose);
    EXPECT_LT(spacing, 0.8 * loose);
    EXPECT_LT(tight, 0.15 * loose);
    EXPECT_LT(tight, 4e-4);
}

// The irradiance vector grid read at the camera's hit (`--method ivg`), 4 camera samples.
double ivg_error(std::array<int, 3> cells, uint64_t photons, const char* what) {
    test::DeviceFrame device(test::load_cornell_box());
    IrradianceVectorGrid grid(device.frame());
    IvgOptions options;
    options.cells = cells;
    options.photons = photons;
    options.seed = 5;
    grid.build(options);
    IvgMethod method(device.frame(), grid);
    auto render = test::image_options<IvgRenderOptions>(kSize, kSize, 4, 5);
    return indirect_relmse(method.render(render), what);
}

// More photons lower the grid's noise; a finer grid (with photons enough for it) lowers its
// interpolation error. Loose: 8³ cells, 5 000 photons.
TEST(Convergence, IrradianceVectorGridErrorFallsWithPhotonsAndResolution) {
    const double loose = ivg_error({8, 8, 8}, 5000, "ivg loose (8^3, 5k photons)");
    const double photons = ivg_error({8, 8, 8}, 500000, "ivg 8^3, 500k photons");
    const double fine = ivg_error({24, 24, 24}, 500000, "ivg 24^3, 500k photons");
    EXPECT_LT(photons, 0.8 * loose);
    EXPECT_LT(fine, 0.6 * photons);
    EXPECT_LT(fine, 0.4 * loose);
}

}  // namespace
}  // namespace rc
