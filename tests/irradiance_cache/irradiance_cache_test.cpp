// Irradiance caching as a method (host/methods/irradiance_cache.cpp): coverage after placement,
// determinism, accuracy against the white furnace's analytic radiance and the Cornell box's
// path-traced reference, and cache files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "image_options.h"
#include "methods/caching/cache_file.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/caching/irradiance_records.h"
#include "scene/device_scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

struct Render {
    Image image;
    PipelineStats stats;
    RecordStore records = irradiance_store(0.0f);  // first level
};

Render render(const Scene& scene, const PipelineSettings& options, Context& context) {
    test::DeviceFrame device(scene, context);
    CachePipeline cache(device.frame());
    Render r;
    r.image = cache.render(options, &r.stats);
    r.records = cache.store(0);
    return r;
}

Render render(const Scene& scene, const PipelineSettings& options) {
    return render(scene, options, test::shared_context());
}

Scene furnace() { return load_scene(test::source_dir() / "scenes/furnace/scene.json"); }

int channel(const Image& image, const std::string& name) {
    for (int c = 0; c < image.channels; ++c) {
        if (image.channel_names[c] == name) {
            return c;
        }
    }
    throw Error("no channel " + name);
}

double channel_mean(const Image& image, const std::string& name) {
    const int c = channel(image, name);
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            sum += image.at(x, y, c);
        }
    }
    return sum / (static_cast<double>(image.width) * image.height);
}

bool bitwise_equal(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// The same records bit for bit: shared parts, host-only data and payloads.
bool same_records(const RecordStore& a, const RecordStore& b) {
    return a.size() == b.size() && a.payloads() == b.payloads() &&
           std::memcmp(a.records().data(), b.records().data(), a.size() * sizeof(shared::Record)) ==
               0 &&
           std::memcmp(a.host_data().data(), b.host_data().data(),
                       a.size() * sizeof(RecordHostData)) == 0;
}

PipelineSettings small_cornell_options() {
    auto options = test::image_options<PipelineSettings>(96, 96, 3, 9);
    options.rays = 256;
    return options;
}

// After placement every camera sample the cache serves has a positive weight sum: the coverage
// layer (the smallest sum over a pixel's served samples) is positive wherever a pixel shows a
// surface (the Cornell box is all diffuse), with one and with two cache levels.
TEST(CachePipeline, PlacementCoversEveryCameraSample) {
    const Scene scene = test::load_cornell_box();
    for (int bounces : {1, 2}) {
        PipelineSettings options = small_cornell_options();
        options.bounces = bounces;
        const Render r = render(scene, options);
        ASSERT_GT(r.stats.records, 0u);
        ASSERT_EQ(r.stats.level_records.size(), static_cast<size_t>(bounces));
        const int coverage = channel(r.image, "coverage.Y");
        const int albedo = channel(r.image, "albedo.G");
        size_t surfaces = 0;
        for (int y = 0; y < r.image.height; ++y) {
            for (int x = 0; x < r.image.width; ++x) {
                if (r.image.at(x, y, albedo) > 0.0f) {
                    ++surfaces;
                    ASSERT_GT(r.image.at(x, y, coverage), 0.0f)
                        << "pixel (" << x << ", " << y << "), " << bounces << " levels";
                }
            }
        }
        EXPECT_GT(surfaces, 8000u);
        // Placement ran coarse to fine, first level first, and at stride 1 until nothing was left
        // uncovered; deeper levels' passes follow the passes they serve.
        ASSERT_FALSE(r.stats.passes.empty());
        EXPECT_EQ(r.stats.passes.front().level, 0);
        EXPECT_EQ(r.stats.passes.front().stride, 16);
        int deepest = 0;
        for (const PlacementPass& pass : r.stats.passes) {
            deepest = std::max(deepest, pass.level);
            EXPECT_GT(pass.records, 0u);
            EXPECT_LE(pass.records, pass.uncovered);
        }
        EXPECT_EQ(deepest, bounces - 1);
    }
}

// The same options give the same records and bitwise the same image, whatever the work-group
// size and launch chunking; another seed gives another image.
TEST(CachePipeline, SameSeedGivesTheSameRecordsAndImageWhateverTheChunking) {
    const Scene scene = test::load_cornell_box();
    PipelineSettings options = small_cornell_options();
    options.bounces = 2;
    const Render a = render(scene, options);
    const Render b = render(scene, options);
    EXPECT_TRUE(same_records(a.records, b.records));
    EXPECT_TRUE(bitwise_equal(a.image, b.image));
    Context chunked(test::chunked_context_options(8, 1000));
    const Render c = render(scene, options, chunked);
    EXPECT_TRUE(same_records(a.records, c.records));
    EXPECT_TRUE(bitwise_equal(a.image, c.image));
    options.seed = 10;
    EXPECT_FALSE(bitwise_equal(a.image, render(scene, options).image));
}

// The white furnace (Le 0.5, albedo 0.75) shows Le / (1 - rho) = 2 everywhere: the cache's
// indirect light and the direct light add up without counting emission twice, with one or two
// cache levels; with at most 3 bounces it shows Le (1 + rho + rho^2 + rho^3), as the path tracer
// does. Within 2%.
TEST(CachePipeline, FurnaceMeanIsWithinTwoPercent) {
    const Scene scene = furnace();
    for (int bounces : {1, 2}) {
        for (int depth : {1000, 3}) {
            auto options = test::image_options<PipelineSettings>(32, 32, 4);
            options.rays = 256;
            options.max_depth = depth;
            options.bounces = bounces;
            const Render r = render(scene, options);
            double expected = 2.0;
            if (depth == 3) {
                expected = 0.5 * (1.0 + 0.75 + 0.5625 + 0.421875);
            }
            for (const char* c : {"R", "G", "B"}) {
                EXPECT_NEAR(channel_mean(r.image, c), expected, 0.02 * expected)
                    << bounces << " levels, max depth " << depth;
            }
        }
    }
}

// With at most one bounce there is no indirect light and no record is made.
TEST(CachePipeline, OneBounceHasNoIndirectLight) {
    PipelineSettings options = small_cornell_options();
    options.max_depth = 1;
    const Render r = render(test::load_cornell_box(), options);
    EXPECT_EQ(r.stats.records, 0u);
    EXPECT_EQ(channel_mean(r.image, "indirect.R"), 0.0);
    EXPECT_GT(channel_mean(r.image, "direct.R"), 0.05);
}

// The method's defaults at 256 x 256, without the records overlay: what the Cornell box's
// reference is compared with.
PipelineSettings default_options_at_256() {
    PipelineSettings options;
    options.width = 256;
    options.height = 256;
    options.records_overlay = false;
    return options;
}

// At its default settings (two cache levels, 4 camera samples per pixel) at 256², the cache's
// indirect light on the Cornell box is within relMSE 2e-4 of the 65 536-spp reference box filtered
// to that size, whose own noise is negligible (measured 6.5e-5, 4032 first-level records), and
// its mean within 1%.
TEST(CachePipeline, CornellBoxIndirectIsCloseToTheReference) {
    const Scene scene = test::load_cornell_box();
    PipelineSettings options = default_options_at_256();
    const Render r = render(scene, options);
    const Image indirect = select_layers(r.image, {"indirect"});
    const ImageError e = image_error(indirect, test::cornell_reference("indirect", 256));
    std::printf("Cornell box indirect: relMSE %.3g, %zu records\n", e.relmse, r.stats.records);
    EXPECT_LT(e.relmse, 2e-4);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(e.test_means[c], e.reference_means[c], 0.01 * e.reference_means[c]);
    }
}

// Deeper cache levels use fewer hemisphere rays (the course, Ward's Radiance chapter: "deeper
// levels use fewer samples"): by default a quarter of --ic-rays, in M x N strata of their own
// (reported), which cuts the rays the records trace; the indirect light against the reference stays
// within 25% of its error with as many rays at every level (measured at 256²: 6.5e-5 against
// 6.3e-5 with 0.44 of the record rays).
TEST(CachePipeline, DeeperLevelsUseFewerRaysAtLittleCost) {
    const Scene scene = test::load_cornell_box();
    PipelineSettings options = default_options_at_256();
    const Render fewer = render(scene, options);
    options.deeper_rays = options.rays;
    const Render same = render(scene, options);
    const RecordSampling quarter = strata_for(options.rays / 4);
    EXPECT_EQ(fewer.stats.deeper_strata_m, quarter.m);
    EXPECT_EQ(fewer.stats.deeper_strata_n, quarter.n);
    EXPECT_EQ(same.stats.deeper_strata_m, same.stats.strata_m);
    EXPECT_EQ(same.stats.deeper_strata_n, same.stats.strata_n);
    EXPECT_LT(fewer.stats.record_rays, 0.6 * same.stats.record_rays);
    const Image reference = test::cornell_reference("indirect", 256);
    const double fewer_error =
        image_error(select_layers(fewer.image, {"indirect"}), reference).relmse;
    const double same_error =
        image_error(select_layers(same.image, {"indirect"}), reference).relmse;
    std::printf("indirect relMSE %.3g (deeper rays %d) against %.3g (%d); record rays %.3g\n",
                fewer_error, quarter.m * quarter.n, same_error, options.rays,
                static_cast<double>(fewer.stats.record_rays) / same.stats.record_rays);
    EXPECT_LT(fewer_error, 1.25 * same_error);
}

// A cache file holds every level's records exactly; loading it for the same view makes no new
// record and renders bitwise the same image.
TEST(CachePipeline, CacheFileRoundTripsExactlyAndIsReused) {
    const Scene scene = test::load_cornell_box();
    const auto dir = test::scratch_dir("ic_cache_file");
    PipelineSettings options = small_cornell_options();
    options.bounces = 2;
    options.cache_out = dir / "cornell.rcc";
    test::DeviceFrame device(scene);
    CachePipeline cache(device.frame());
    PipelineStats stats;
    const Image first = cache.render(options, &stats);
    const std::vector<RecordStore> levels =
        read_cache_file(options.cache_out, irradiance_cache_key(scene, options.accuracy));
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_TRUE(same_records(levels[0], cache.store(0)));
    EXPECT_TRUE(same_records(levels[1], cache.store(1)));
    EXPECT_GT(levels[1].size(), 0u);

    PipelineSettings reuse = options;
    reuse.cache_in = options.cache_out;
    reuse.cache_out.clear();
    PipelineStats reused;
    const Image second = cache.render(reuse, &reused);
    EXPECT_EQ(reused.loaded_records, levels[0].size() + levels[1].size());
    EXPECT_EQ(reused.records, levels[0].size());
    EXPECT_TRUE(bitwise_equal(first, second));
}

void expect_refused(const std::filesystem::path& file, const Scene& scene, float accuracy,
                    const std::string& message) {
    try {
        read_cache_file(file, irradiance_cache_key(scene, accuracy));
        ADD_FAILURE() << file << " was accepted";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
    }
}

// Corrupt, truncated, foreign and mismatched files are refused with an error naming the file.
TEST(CachePipeline, CorruptAndMismatchedCacheFilesAreRefused) {
    const Scene scene = test::load_cornell_box();
    const auto dir = test::scratch_dir("ic_cache_refused");
    const std::filesystem::path good = dir / "good.rcc";
    PipelineSettings options = small_cornell_options();
    options.width = 32;
    options.height = 32;
    options.cache_out = good;
    render(scene, options);
    const std::string bytes = read_file(good);
    ASSERT_GT(bytes.size(), 200u);
    EXPECT_NO_THROW(read_cache_file(good, irradiance_cache_key(scene, options.accuracy)));

    std::string flipped = bytes;
    flipped[bytes.size() / 2] ^= 0x10;
    write_file_atomically(dir / "flipped.rcc", flipped);
    expect_refused(dir / "flipped.rcc", scene, options.accuracy, "checksum");

    write_file_atomically(dir / "truncated.rcc", bytes.substr(0, bytes.size() - 7));
    expect_refused(dir / "truncated.rcc", scene, options.accuracy, "corrupt");

    std::string version = bytes;
    version[8] = 99;
    write_file_atomically(dir / "version.rcc", version);
    expect_refused(dir / "version.rcc", scene, options.accuracy, "version 99");

    write_file_atomically(dir / "foreign.rcc", "P6\n1 1\n255\n\0\0\0");
    expect_refused(dir / "foreign.rcc", scene, options.accuracy, "not a radcache irradiance");

    expect_refused(dir / "missing.rcc", scene, options.accuracy, "not found");
    expect_refused(good, furnace(), options.accuracy, "another scene");
    expect_refused(good, scene, 0.5f, "accuracy");
}

}  // namespace
}  // namespace rc
