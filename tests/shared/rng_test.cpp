// The counter-based RNG: Random123's known answers for Philox4x32-10, the same words on host and
// device, and uniformity by a chi-square test.
#include "shared/rng.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

namespace rc {
namespace {

using shared::uint;

// Random123 tests/kat_vectors, the three "philox4x32 10" lines: counter, key, result.
struct KnownAnswer {
    uint counter[4];
    uint key[2];
    uint result[4];
};
const KnownAnswer kKnownAnswers[] = {
    {{0, 0, 0, 0}, {0, 0}, {0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8}},
    {{0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff},
     {0xffffffff, 0xffffffff},
     {0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd}},
    {{0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344},
     {0xa4093822, 0x299f31d0},
     {0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1}},
};

TEST(Rng, HostPhiloxMatchesRandom123KnownAnswers) {
    for (const KnownAnswer& k : kKnownAnswers) {
        uint out[4];
        shared::rc_philox4x32_10(k.counter[0], k.counter[1], k.counter[2], k.counter[3], k.key[0],
                                 k.key[1], out);
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(out[i], k.result[i]);
        }
    }
}

TEST(Rng, DevicePhiloxMatchesRandom123KnownAnswers) {
    Context& context = test::shared_context();
    std::vector<uint> inputs;
    for (const KnownAnswer& k : kKnownAnswers) {
        inputs.insert(inputs.end(),
                      {k.counter[0], k.counter[1], k.counter[2], k.counter[3], k.key[0], k.key[1]});
    }
    const Buffer<uint> in(context, inputs, "philox_inputs");
    Buffer<uint> out(context, 4 * std::size(kKnownAnswers), "philox_outputs");
    Kernel kernel = context.kernel("rng_probe.cl", "philox_blocks");
    context.launch(kernel, std::size(kKnownAnswers), in, out);
    const std::vector<uint> words = out.download();
    for (size_t k = 0; k < std::size(kKnownAnswers); ++k) {
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(words[4 * k + i], kKnownAnswers[k].result[i]);
        }
    }
}

TEST(Rng, DeviceStreamsEqualHostStreams) {
    Context& context = test::shared_context();
    const uint streams = 4096;
    const uint dimensions = 11;  // crosses block boundaries (4 words per block)
    const uint seed_lo = 0x1234567u;
    const uint seed_hi = 0x89abcdefu;
    const uint sample = 77;
    Buffer<uint> out(context, streams * dimensions, "rng_words");
    Kernel kernel = context.kernel("rng_probe.cl", "rng_stream_words");
    context.launch(kernel, streams, seed_lo, seed_hi, sample, dimensions, out);
    const std::vector<uint> device = out.download();
    for (uint s = 0; s < streams; ++s) {
        shared::RngStream rng = shared::rc_rng_stream(seed_lo, seed_hi, s, sample);
        for (uint d = 0; d < dimensions; ++d) {
            const uint host = shared::rc_rng_next_uint(&rng);
            ASSERT_EQ(device[s * dimensions + d], host) << "stream " << s << " dimension " << d;
            ASSERT_EQ(host, shared::rc_rng_word(seed_lo, seed_hi, s, sample, d));
        }
    }
}

// Pearson's chi-square over 256 equal bins of 2^20 floats; 255 degrees of freedom: the 99.99%
// quantile is about 356, so a correct generator fails this with probability 1e-4 (and, the seed
// being fixed, the outcome is deterministic).
TEST(Rng, FloatsAreUniformByChiSquare) {
    const int bins = 256;
    const uint count = 1u << 20;
    std::vector<double> observed(bins, 0.0);
    for (uint i = 0; i < count / 4; ++i) {
        shared::RngStream rng = shared::rc_rng_stream(42, 0, i, 3);
        for (int d = 0; d < 4; ++d) {
            const float u = shared::rc_rng_next_float(&rng);
            ASSERT_GE(u, 0.0f);
            ASSERT_LT(u, 1.0f);
            observed[static_cast<int>(u * bins)] += 1.0;
        }
    }
    const double expected = static_cast<double>(count) / bins;
    double chi2 = 0.0;
    for (double o : observed) {
        chi2 += (o - expected) * (o - expected) / expected;
    }
    EXPECT_LT(chi2, 356.0);
    // And not suspiciously perfect (the 0.01% lower quantile is about 171).
    EXPECT_GT(chi2, 171.0);
}

// Neighbouring streams and samples are uncorrelated: the correlation coefficient of the first
// word of stream i and of stream i + 1 over 2^18 pairs stays within 5 standard errors of 0.
TEST(Rng, NeighbouringStreamsAreUncorrelated) {
    const int n = 1 << 18;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < n; ++i) {
        const double x = shared::rc_uint_to_unit_float(shared::rc_rng_word(9, 0, i, 0, 0));
        const double y = shared::rc_uint_to_unit_float(shared::rc_rng_word(9, 0, i + 1, 0, 0));
        sx += x;
        sy += y;
        sxx += x * x;
        syy += y * y;
        sxy += x * y;
    }
    const double cov = sxy / n - (sx / n) * (sy / n);
    const double r =
        cov / std::sqrt((sxx / n - (sx / n) * (sx / n)) * (syy / n - (sy / n) * (sy / n)));
    EXPECT_LT(std::fabs(r), 5.0 / std::sqrt(static_cast<double>(n)));
}

}  // namespace
}  // namespace rc
