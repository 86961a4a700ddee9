// Irradiance caching by time in passes (records/record_passes.h) on the Cornell box: a later pass
// draws exactly the camera samples a longer single render gives the same indices (so a pixel's
// Sobol' points keep their stratification), keeps every record of the passes before and adds
// records only where its own samples are not covered, and leaves none of them served without
// weight (the splat buffer of the whole cache, as in IcSplat's test).
#include <gtest/gtest.h>

#include <cstring>

#include "image_options.h"
#include "methods/caching/cache_pipeline.h"
#include "test_support.h"

namespace rc {
namespace {

PipelineSettings pass_options(int first_sample, int spp) {
    auto options = test::image_options<PipelineSettings>(40, 32, spp, 5);
    options.rays = 64;
    options.bounces = 1;
    options.records_overlay = false;
    options.first_sample = first_sample;
    return options;
}

bool same_hit(const shared::GBufferSample& a, const shared::GBufferSample& b) {
    return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
           std::memcmp(&a.normal, &b.normal, sizeof a.normal) == 0 && a.primitive == b.primitive &&
           a.footprint == b.footprint;
}

TEST(RecordPasses, ALaterPassDrawsTheSamplesOfALongerRender) {
    test::DeviceFrame cornell(test::load_cornell_box());
    CachePipeline whole(cornell.frame());
    whole.render(pass_options(0, 5));
    const std::vector<shared::GBufferSample> all = whole.camera_samples();
    CachePipeline split(cornell.frame());
    split.render(pass_options(0, 2));
    const std::vector<shared::GBufferSample> first = split.camera_samples();
    split.render_more(pass_options(2, 3));
    const std::vector<shared::GBufferSample> later = split.camera_samples();
    const size_t pixels = 40 * 32;
    ASSERT_EQ(all.size(), pixels * 5);
    ASSERT_EQ(first.size(), pixels * 2);
    ASSERT_EQ(later.size(), pixels * 3);
    size_t differing_pixels = 0;
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t s = 0; s < 2; ++s) {
            ASSERT_TRUE(same_hit(first[p * 2 + s], all[p * 5 + s])) << "pixel " << p << " " << s;
        }
        for (size_t s = 0; s < 3; ++s) {
            ASSERT_TRUE(same_hit(later[p * 3 + s], all[p * 5 + 2 + s]))
                << "pixel " << p << " sample " << 2 + s;
        }
        differing_pixels += same_hit(later[p * 3], first[p * 2]) ? 0 : 1;
    }
    // (The later pass's samples are new ones, not the first pass's again.)
    EXPECT_GT(differing_pixels, pixels / 2);
}

TEST(RecordPasses, ALaterPassKeepsTheRecordsAndCoversItsSamples) {
    test::DeviceFrame cornell(test::load_cornell_box());
    CachePipeline cache(cornell.frame());
    cache.render(pass_options(0, 1));
    const RecordStore before = cache.store(0);
    PipelineStats stats;
    cache.render_more(pass_options(1, 4), &stats);
    const RecordStore& after = cache.store(0);
    ASSERT_GT(before.size(), 20u);
    ASSERT_GE(after.size(), before.size());
    for (size_t i = 0; i < before.size(); ++i) {
        ASSERT_EQ(std::memcmp(&before.records()[i].position, &after.records()[i].position,
                              sizeof before.records()[i].position),
                  0)
            << "record " << i << " moved";
    }
    // New records only where the new samples were uncovered: far fewer than the first pass made.
    EXPECT_LT(after.size() - before.size(), before.size() / 2);
    EXPECT_EQ(stats.records, after.size());
    const std::vector<shared::GBufferSample> samples = cache.camera_samples();
    const std::vector<shared::float4> splat = cache.splat(after, cache.camera(), 4, samples);
    size_t served = 0;
    for (size_t q = 0; q < samples.size(); ++q) {
        if (samples[q].served != 0) {
            ++served;
            EXPECT_GT(splat[q].w, 0.0f) << "sample " << q << " is served but uncovered";
        }
    }
    EXPECT_GT(served, samples.size() / 2);
}

}  // namespace
}  // namespace rc
