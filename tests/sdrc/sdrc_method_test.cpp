// Spatial directional radiance caching through the whole `sdrc` path
// (host/methods/sdrc/sdrc_cache.h): the glossy buffer irradiance caching's render pass reads,
// against independent oracles (a quadrature of the BRDF, path-traced references).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "glossy_render.h"
#include "glossy_scenes.h"
#include "image/image_error.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/sdrc/sdrc_cache.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

using test::render_sdrc;
using test::SdrcRender;

// Under a constant sky L with no occluder, every radiance sample is L, so the glossy-indirect
// layer must be L albedo(w_o) at each pixel (w_o: its centre's; the albedo, the integral of
// f_s cos over the hemisphere with unit rho_s, by the test's own quadrature of the BRDF). The
// estimate is M lobe directions per camera sample weighted f_s cos / p, so its noise is that
// weight's (for Phong (n + 2) / (n + 1) cos theta_i, about 6% here) over 4 x 16 directions a
// pixel, 0.75%; RGBE adds at most 1/256 of the largest channel. Bounds: 4% per pixel (over 5
// sigma), 1% over the image (measured in the printout).
void expect_white_sky(const std::string& name, const std::string& json, const Material& material) {
    constexpr int kSize = 16;
    // Seen steeply from above: every pixel's lobe clear of the horizon, so the estimate's weights
    // barely vary.
    test::DeviceFrame device(
        test::sky_plane_scene("sdrc_white_sky_" + name, "[0, 5, -1.5]", json, "[0.8, 0.6, 0.45]"));
    SdrcOptions options;
    options.count_emission = true;
    options.interp = 16;
    const SdrcRender r = render_sdrc(device, test::glossy_ic_options(kSize, 4, 3, 64), options);
    ASSERT_GT(r.stats.records, 0u);
    const Image glossy = select_layers(r.image, {"glossy-indirect"});
    const test::RelativeErrors errors =
        test::sky_plane_errors(glossy, device.scene.camera, material, {0.8, 0.6, 0.45},
                               [&](int x, int y, int c, double error, double expected) {
                                   EXPECT_LT(std::abs(error), 0.04)
                                       << name << " pixel " << x << ", " << y << " channel " << c
                                       << ": " << glossy.at(x, y, c) << " vs " << expected;
                               });
    std::printf(
        "white sky %s: %zu records, %llu L-tree samples, hit rate %.3f; relative error: "
        "largest %.4f, mean %.4f\n",
        name.c_str(), r.stats.records, static_cast<unsigned long long>(r.stats.ltree_nodes),
        static_cast<double>(r.stats.answered) / static_cast<double>(r.stats.directions),
        errors.largest, errors.mean);
    EXPECT_LT(std::abs(errors.mean), 0.01) << name;
}

TEST(SdrcMethod, WhiteSkyPhongPlaneReflectsRadianceTimesAlbedo) {
    expect_white_sky("phong64", R"({"type": "phong", "diffuse": 0, "specular": 1, "exponent": 64})",
                     test::pure_phong(64.0f));
}

TEST(SdrcMethod, WhiteSkyWardPlaneReflectsRadianceTimesAlbedo) {
    Material ward = test::pure_phong(1.0f);
    ward.kind = MaterialKind::kWard;
    ward.alpha_x = 0.18f;
    ward.alpha_y = 0.09f;
    expect_white_sky(
        "ward",
        R"({"type": "ward", "diffuse": 0, "specular": 1, "alpha_x": 0.18, "alpha_y": 0.09})", ward);
}

// On sharp lobes, where radiance caching's spherical harmonics blur or give up (exponents 16 to
// 256), SDRC's indirect light on the sphere (relMSE against a 1024-spp path-traced reference)
// beats path tracing the lobe at the same camera samples (irradiance caching with the same
// diffuse records), and its cache answers most directions.
TEST(SdrcMethod, SharpLobesBeatMonteCarloAtTheSameSamples) {
    constexpr int kSize = 32;
    for (int exponent : {16, 64, 256}) {
        test::DeviceFrame device(test::phong_sphere_scene(exponent, "sdrc"));
        const Image reference = test::path_traced_indirect(device, kSize);
        const PipelineSettings ic = test::glossy_ic_options(kSize, 8, 5);
        const SdrcRender r = render_sdrc(device, ic);
        const test::SphereErrors e = test::sphere_errors(device, ic, r.image, reference);
        const double hit_rate =
            static_cast<double>(r.stats.answered) / static_cast<double>(r.stats.directions);
        std::printf(
            "Phong %3d: %zu records x %d samples, hit rate %.3f, %llu misses; sphere (%zu "
            "pixels) indirect relMSE sdrc %.3g, Monte Carlo lobe %.3g\n",
            exponent, r.stats.records, r.stats.samples, hit_rate,
            static_cast<unsigned long long>(r.stats.misses), e.pixels, e.glossy, e.monte_carlo);
        ASSERT_GT(e.pixels, 50u);
        EXPECT_LT(e.glossy, e.monte_carlo) << "exponent " << exponent;
        EXPECT_GT(hit_rate, 0.5) << "exponent " << exponent;
    }
}

// glossy-box at 64², 4 camera samples: the indirect layer against the shipped reference (box
// filtered), means within 1.5% per channel and relMSE below the bound.
TEST(SdrcMethod, GlossyBoxIndirectIsCloseToTheReference) {
    constexpr int kSize = 64;
    test::DeviceFrame device(load_scene(test::source_dir() / "scenes/glossy-box/scene.json"));
    const SdrcRender r = render_sdrc(device, test::glossy_ic_options(kSize, 4, 7));
    const Image reference = test::scene_reference("glossy-box", "indirect", kSize);
    const ImageError e = image_error(select_layers(r.image, {"indirect"}), reference);
    std::printf(
        "sdrc glossy-box %d^2: %zu records, hit rate %.3f, indirect relMSE %.3g, means %.4f "
        "%.4f %.4f vs %.4f %.4f %.4f\n",
        kSize, r.stats.records,
        static_cast<double>(r.stats.answered) / static_cast<double>(r.stats.directions), e.relmse,
        e.test_means[0], e.test_means[1], e.test_means[2], e.reference_means[0],
        e.reference_means[1], e.reference_means[2]);
    EXPECT_GT(r.stats.records, 0u);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(e.test_means[c], e.reference_means[c], 0.015 * e.reference_means[c]);
    }
    EXPECT_LT(e.relmse, 0.02);
}

// The kettle (the paper's case: anisotropic Ward 0.18 / 0.09 reflecting checkered walls) at 64²,
// 4 camera samples, 4 directions each: on the kettle's pixels (those SDRC serves), the indirect
// layer against the shipped reference (box filtered) has a relMSE below 0.05 (measured 0.030) and
// below half of Monte Carlo's at the same camera samples (irradiance caching with the same
// diffuse records, the lobe path traced; measured 0.17x), and its mean is within 2% of the
// reference's (measured 0.7%).
TEST(SdrcMethod, KettleIndirectBeatsMonteCarloAgainstTheReference) {
    constexpr int kSize = 64;
    test::DeviceFrame device(load_scene(test::source_dir() / "scenes/kettle/scene.json"));
    const PipelineSettings ic = test::glossy_ic_options(kSize, 4, 13);
    SdrcOptions sdrc;
    sdrc.interp = 4;
    const SdrcRender r = render_sdrc(device, ic, sdrc);
    const Image mc = CachePipeline(device.frame()).render(ic);
    const Image reference = test::scene_reference("kettle", "indirect", kSize);
    const Image mask = select_layers(r.image, {"sdrc-hits"});
    size_t pixels = 0;
    const Image indirect = select_layers(r.image, {"indirect"});
    const double sdrc_error = test::masked_relmse(indirect, reference, mask, &pixels);
    const double mc_error =
        test::masked_relmse(select_layers(mc, {"indirect"}), reference, mask, &pixels);
    double mean = 0.0;
    double reference_mean = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (mask.at(x, y, 0) > 0.0f) {
                for (int c = 0; c < 3; ++c) {
                    mean += indirect.at(x, y, c);
                    reference_mean += reference.at(x, y, c);
                }
            }
        }
    }
    std::printf(
        "sdrc kettle %d^2: %zu records, hit rate %.3f; kettle (%zu pixels) indirect relMSE sdrc "
        "%.3g, Monte Carlo lobe %.3g; mean %.4f vs %.4f\n",
        kSize, r.stats.records,
        static_cast<double>(r.stats.answered) / static_cast<double>(r.stats.directions), pixels,
        sdrc_error, mc_error, mean / (3.0 * pixels), reference_mean / (3.0 * pixels));
    ASSERT_GT(pixels, 500u);
    EXPECT_LT(sdrc_error, 0.05);
    EXPECT_LT(sdrc_error, 0.5 * mc_error);
    EXPECT_NEAR(mean, reference_mean, 0.02 * reference_mean);
}

Image render_sdrc_with(size_t local_size, size_t max_chunk, size_t batch, const Scene& scene) {
    Context context(test::chunked_context_options(local_size, max_chunk));
    test::DeviceFrame device(scene, context);
    SdrcOptions sdrc;
    sdrc.interp = 2;
    sdrc.record_batch = batch;
    sdrc.round_batch = batch;
    return render_sdrc(device, test::glossy_ic_options(16, 2, 99, 128), sdrc).image;
}

// Same seed and options: the same image, bit for bit, whatever the chunking, the work-group size
// and the record and interpolation batch sizes (the L-trees change only between rounds, in sample
// order).
TEST(SdrcMethod, ImageIsBitwiseIdenticalAcrossRunsChunksWorkGroupsAndBatches) {
    const Scene scene = test::phong_sphere_scene(64, "sdrc");
    const Image reference = render_sdrc_with(0, 0, 0, scene);
    EXPECT_TRUE(test::bitwise_equal(reference, render_sdrc_with(0, 0, 0, scene))) << "second run";
    EXPECT_TRUE(test::bitwise_equal(reference, render_sdrc_with(8, 1000, 7, scene)))
        << "local 8, chunk 1000, batch 7";
    EXPECT_TRUE(test::bitwise_equal(reference, render_sdrc_with(32, 4096, 3, scene)))
        << "local 32, chunk 4096, batch 3";
    const Image glossy = select_layers(reference, {"glossy-indirect"});
    EXPECT_GT(*std::max_element(glossy.pixels.begin(), glossy.pixels.end()), 0.0f);
}

// A memory cap the L-trees exceed stops the render with an error naming the option.
TEST(SdrcMethod, MemoryCapTooSmallFailsWithAClearError) {
    test::DeviceFrame device(test::phong_sphere_scene(64, "sdrc"));
    SdrcOptions sdrc;
    sdrc.memory_mib = 0.01;
    try {
        render_sdrc(device, test::glossy_ic_options(16, 2, 5), sdrc);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--sdrc-memory"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rc
