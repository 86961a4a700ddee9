// A render by time in passes (methods/sample_passes.h), driven by a clock of the test's own: a
// pass costs a fixed cache build (the first only) plus a fixed time a sample per pixel, so what
// the budget holds is known exactly. Each pass's image holds, in every pixel, the mean of its
// sample indices: the frame's image must then be the mean of 0 .. spp - 1, whatever the split.
#include "methods/sample_passes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"

namespace rc {
namespace {

struct FakeRender {
    double cache_seconds = 0.0;   // the first pass's build
    double sample_seconds = 0.0;  // a sample per pixel
    bool tells_cache = true;      // FrameResult::cache_seconds given
    double now = 0.0;
    std::vector<SamplePass> passes;

    FrameResult pass(const SamplePass& pass) {
        now += (pass.first == 0 ? cache_seconds : 0.0) + sample_seconds * pass.spp;
        passes.push_back(pass);
        FrameResult result;
        result.image = Image(3, 2, 1);
        for (float& v : result.image.pixels) {
            v = static_cast<float>(pass.first + 0.5 * (pass.spp - 1));  // mean of its indices
        }
        result.spp = pass.spp;
        result.rays = 10u * static_cast<uint64_t>(pass.spp);
        result.stats = {{"records", 7}};
        // (A later pass may tell a cumulative figure larger than its own time: ignored.)
        result.cache_seconds = !tells_cache ? 0.0 : pass.first == 0 ? cache_seconds : 1e3;
        return result;
    }

    FrameResult render(double budget, int max_spp) {
        SamplePassBudget b{budget, max_spp, [this] { return now; }};
        return render_sample_passes(b, {}, [this](const SamplePass& p) { return pass(p); });
    }
};

TEST(SamplePasses, SpendTheBudgetOnContiguousPassesAndEndBeforeIt) {
    for (const double cache : {0.0, 0.3, 2.0, 4.99, 5.5}) {
        for (const double sample : {0.001, 0.05, 0.7}) {
            for (const int max_spp : {1, 4, 64}) {
                for (const bool tells : {true, false}) {
                    FakeRender fake{cache, sample, tells};
                    const double budget = 5.0;
                    const FrameResult result = fake.render(budget, max_spp);
                    SCOPED_TRACE(testing::Message() << "cache " << cache << " s, sample " << sample
                                                    << " s, at most " << max_spp << " a pass"
                                                    << (tells ? "" : ", cache seconds not told"));
                    ASSERT_FALSE(fake.passes.empty());
                    // The first pass builds the cache with one sample per pixel; the others follow
                    // on without gaps, none larger than max_spp or than the samples before it.
                    EXPECT_EQ(fake.passes[0].first, 0);
                    EXPECT_EQ(fake.passes[0].spp, 1);
                    int samples = 0;
                    for (const SamplePass& pass : fake.passes) {
                        EXPECT_EQ(pass.first, samples);
                        EXPECT_GE(pass.spp, 1);
                        if (pass.first > 0) {
                            EXPECT_LE(pass.spp, max_spp);
                            EXPECT_LE(pass.spp, samples);
                        }
                        samples += pass.spp;
                    }
                    EXPECT_EQ(result.spp, samples);
                    EXPECT_EQ(result.rays, 10u * static_cast<uint64_t>(samples));
                    // Ends within the budget, with less than one more sample's time left (not told
                    // the cache's time, the first pass's cost bounds a sample's until a second).
                    if (cache + sample <= budget) {
                        EXPECT_LE(fake.now, budget + 1e-12);
                        EXPECT_LT(budget - fake.now, tells || fake.passes.size() > 1
                                                         ? sample + 1e-12
                                                         : cache + sample + 1e-12);
                    } else {
                        EXPECT_EQ(fake.passes.size(), 1u);  // the first pass alone exceeds it
                    }
                    // The image is the mean of every sample index.
                    for (float v : result.image.pixels) {
                        EXPECT_NEAR(v, 0.5 * (samples - 1), 1e-6 * samples);
                    }
                    // The split reported adds up.
                    const nlohmann::json& time = result.stats["time"];
                    EXPECT_EQ(time["passes"].get<size_t>(), fake.passes.size());
                    EXPECT_EQ(time["spp"].get<int>(), samples);
                    EXPECT_EQ(result.stats["spp"].get<int>(), samples);
                    EXPECT_NEAR(time["first_pass_seconds"].get<double>() +
                                    time["later_passes_seconds"].get<double>(),
                                fake.now, 1e-9);
                    EXPECT_EQ(result.stats["passes"].size(), fake.passes.size() - 1);
                    EXPECT_EQ(result.stats["records"].get<int>(), 7);
                }
            }
        }
    }
}

TEST(SamplePasses, WeightedMeanOfImages) {
    Image mean;
    Image a(1, 1, 2);
    a.pixels = {1.0f, 4.0f};
    Image b(1, 1, 2);
    b.pixels = {3.0f, 0.0f};
    add_weighted(&mean, 0.0, a, 1.0);
    EXPECT_EQ(mean.pixels, a.pixels);
    add_weighted(&mean, 1.0, b, 3.0);
    EXPECT_FLOAT_EQ(mean.pixels[0], 2.5f);
    EXPECT_FLOAT_EQ(mean.pixels[1], 1.0f);
    EXPECT_THROW(add_weighted(&mean, 4.0, Image(2, 1, 2), 1.0), Error);
}

}  // namespace
}  // namespace rc
