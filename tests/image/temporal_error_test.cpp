// The temporal error (flicker) of frame sequences (host/image/temporal_error.cpp) and
// `radcache compare --frames` on synthetic sequences whose answers are known in closed form:
// identical sequences, a fixed offset image (per-frame error, no flicker), an offset that
// alternates in sign (flicker of 4 c^2 over r^2 + 0.01), and references with known noise.
#include "image/temporal_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "image/image_error.h"
#include "image/image_io.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

constexpr int kWidth = 16;
constexpr int kHeight = 8;

Image rgb_image(int width, int height) {
    Image image(width, height, 3);
    image.channel_names = {"R", "G", "B"};
    return image;
}

// Reference frame f: values k / 64 in [0, 2], different in every frame. Multiples of 1/64 this
// small are exact in float and so are their sums with the offsets below, so that a difference
// that cancels in exact arithmetic cancels in the images too.
Image reference_frame(int frame) {
    Image image = rgb_image(kWidth, kHeight);
    std::mt19937 rng(100 + frame);
    std::uniform_int_distribution<int> step(0, 128);
    for (float& v : image.pixels) {
        v = static_cast<float>(step(rng)) / 64.0f;
    }
    return image;
}

// `image` + `offset` on the pixels x < `columns` (default all).
Image plus(const Image& image, float offset, int columns = kWidth) {
    Image sum = image;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < columns; ++x) {
            for (int c = 0; c < image.channels; ++c) {
                sum.at(x, y, c) += offset;
            }
        }
    }
    return sum;
}

// The mean of 1 / (r^2 + 0.01) over the values of `reference` in the pixels x < `columns`.
double mean_inverse_denominator(const Image& reference, int columns = kWidth) {
    double sum = 0.0;
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < columns; ++x) {
            for (int c = 0; c < reference.channels; ++c) {
                const double r = reference.at(x, y, c);
                sum += 1.0 / (r * r + 0.01);
            }
        }
    }
    return sum / (static_cast<double>(columns) * reference.height * reference.channels);
}

TEST(TemporalError, IsZeroForIdenticalSequences) {
    const Image r0 = reference_frame(0);
    const Image r1 = reference_frame(1);
    const TemporalError e = temporal_error(r0, r1, r0, r1, "same");
    EXPECT_EQ(e.temporal_error, 0.0);
    EXPECT_EQ(e.pixels, static_cast<size_t>(kWidth * kHeight));
    EXPECT_FALSE(e.temporal_error_net.has_value());
}

// v_f = r_f + g for one fixed image g: every frame is wrong, but by the same amount, so nothing
// flickers.
TEST(TemporalError, IsZeroForAFixedOffsetImageWhileEachFrameIsWrong) {
    Image offset = rgb_image(kWidth, kHeight);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> step(-16, 16);
    for (float& v : offset.pixels) {
        v = static_cast<float>(step(rng)) / 64.0f;
    }
    Image v0 = reference_frame(0);
    Image v1 = reference_frame(1);
    for (size_t i = 0; i < v0.pixels.size(); ++i) {
        v0.pixels[i] += offset.pixels[i];
        v1.pixels[i] += offset.pixels[i];
    }
    EXPECT_EQ(temporal_error(v0, v1, reference_frame(0), reference_frame(1)).temporal_error, 0.0);
    EXPECT_GT(image_error(v0, reference_frame(0)).relmse, 1e-3);
    EXPECT_GT(image_error(v1, reference_frame(1)).relmse, 1e-3);
}

// v_f = r_f + (-1)^f c: the change between frames is off by 2c in every value, so the temporal
// error of frame f is 4 c^2 mean(1 / (r_f^2 + 0.01)), four times that frame's relMSE
// (c^2 mean(...)); a drift v_f = r_f + f c is off by c: c^2 mean(...).
TEST(TemporalError, AlternatingOffsetGivesFourTimesTheOffsetsSquare) {
    const float c = 0.25f;
    for (int f = 1; f < 4; ++f) {
        SCOPED_TRACE(f);
        const Image r0 = reference_frame(f - 1);
        const Image r1 = reference_frame(f);
        const float sign = f % 2 == 0 ? 1.0f : -1.0f;
        const Image v0 = plus(r0, -sign * c);
        const Image v1 = plus(r1, sign * c);
        const double expected = 4.0 * c * c * mean_inverse_denominator(r1);
        EXPECT_NEAR(temporal_error(v0, v1, r0, r1).temporal_error, expected, 1e-12 * expected);
        EXPECT_NEAR(temporal_error(v0, v1, r0, r1).temporal_error, 4.0 * image_error(v1, r1).relmse,
                    1e-12 * expected);
        const double drift =
            temporal_error(plus(r0, (f - 1) * c), plus(r1, f * c), r0, r1).temporal_error;
        EXPECT_NEAR(drift, c * c * mean_inverse_denominator(r1), 1e-12 * expected);
    }
}

// The offset alternates on the left half only: a mask of the left half sees all of it, one of
// the right half none; a mask that selects nothing or has another size is refused.
TEST(TemporalError, MaskTakesTheFigureOverItsPixelsOnly) {
    const float c = 0.5f;
    const Image r0 = reference_frame(0);
    const Image r1 = reference_frame(1);
    const Image v0 = plus(r0, -c, kWidth / 2);
    const Image v1 = plus(r1, c, kWidth / 2);
    Image left(kWidth, kHeight, 1);
    Image right(kWidth, kHeight, 1);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            (x < kWidth / 2 ? left : right).at(x, y, 0) = 1.0f;
        }
    }
    const TemporalError on_left = temporal_error(v0, v1, r0, r1, "left", PixelMask{&left});
    EXPECT_EQ(on_left.pixels, static_cast<size_t>(kWidth / 2 * kHeight));
    const double expected = 4.0 * c * c * mean_inverse_denominator(r1, kWidth / 2);
    EXPECT_NEAR(on_left.temporal_error, expected, 1e-12 * expected);
    EXPECT_EQ(temporal_error(v0, v1, r0, r1, "right", PixelMask{&right}).temporal_error, 0.0);
    EXPECT_NEAR(temporal_error(v0, v1, r0, r1).temporal_error, expected / 2.0, 1e-12 * expected);
    const Image none(kWidth, kHeight, 1);
    EXPECT_THROW(temporal_error(v0, v1, r0, r1, "none", PixelMask{&none}), Error);
    const Image wide(kWidth + 1, kHeight, 1);
    EXPECT_THROW(temporal_error(v0, v1, r0, r1, "wide", PixelMask{&wide}), Error);
}

TEST(TemporalError, RefusesFramesOfAnotherSizeOrChannelCount) {
    const Image r0 = reference_frame(0);
    const Image r1 = reference_frame(1);
    const Image wide = rgb_image(kWidth + 1, kHeight);
    const Image grey(kWidth, kHeight, 1);
    for (const Image* odd : {&wide, &grey}) {
        EXPECT_THROW(temporal_error(*odd, r1, r0, r1), Error);
        EXPECT_THROW(temporal_error(r0, *odd, r0, r1), Error);
        EXPECT_THROW(temporal_error(r0, r1, *odd, r1), Error);
        EXPECT_THROW(temporal_error(r0, r1, r0, *odd), Error);
    }
}

// Two frames of constant means mu_0, mu_1; the references carry independent Gaussian noise of
// variance sigma_f^2 / spp_f (sigma_f their per-sample stddev layer, different per frame so that
// a mix-up shows), the test frames independent noise of variance sigma_test^2 (0: exact).
struct NoisyPair {
    Image test[2];
    Image reference[2];
    Image stddev[2];
};

constexpr int kNoiseSize = 256;
constexpr double kMu[2] = {0.5, 0.6};
constexpr double kSigma[2] = {0.16, 0.32};
constexpr double kSpp[2] = {256.0, 1024.0};

NoisyPair noisy_pair(double sigma_test, unsigned seed) {
    NoisyPair pair;
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int f = 0; f < 2; ++f) {
        pair.test[f] = rgb_image(kNoiseSize, kNoiseSize);
        pair.reference[f] = rgb_image(kNoiseSize, kNoiseSize);
        pair.stddev[f] = rgb_image(kNoiseSize, kNoiseSize);
        for (size_t i = 0; i < pair.test[f].pixels.size(); ++i) {
            pair.stddev[f].pixels[i] = static_cast<float>(kSigma[f]);
            pair.reference[f].pixels[i] =
                static_cast<float>(kMu[f] + kSigma[f] / std::sqrt(kSpp[f]) * normal(rng));
            pair.test[f].pixels[i] = static_cast<float>(kMu[f] + sigma_test * normal(rng));
        }
    }
    return pair;
}

// Every value's term is ((e_test1 - e_test0) - (e_ref1 - e_ref0))^2 / (r1^2 + 0.01): a squared
// Gaussian of variance s^2 = 2 sigma_test^2 + Var(r0) + Var(r1) over about x = mu_1^2 + 0.01.
// Its mean over n values has mean s^2 / x and standard error s^2 / x sqrt(2 / n); the noisy
// denominator biases it by about f'' Var(r1) / 2 relative to f = 1 / x (f'' = -2 / x^2 + 8 mu^2 /
// x^3): 0.3 % here, bounded below by 1 % of the mean.
struct Expected {
    double mean = 0.0;
    double tolerance = 0.0;  // 5 standard errors and the bias bound
};

Expected expected_temporal_error(double sigma_test, bool reference_share) {
    const double reference_variance =
        kSigma[0] * kSigma[0] / kSpp[0] + kSigma[1] * kSigma[1] / kSpp[1];
    const double s2 = 2.0 * sigma_test * sigma_test + reference_variance;
    const double x = kMu[1] * kMu[1] + 0.01;
    const double n = 3.0 * kNoiseSize * kNoiseSize;
    Expected e;
    e.mean = (s2 - (reference_share ? 0.0 : reference_variance)) / x;
    e.tolerance = 5.0 * s2 / x * std::sqrt(2.0 / n) + 0.01 * s2 / x;
    return e;
}

TEST(TemporalErrorNet, SubtractsBothReferenceFramesNoise) {
    const double sigma_test = 0.03;
    const NoisyPair p = noisy_pair(sigma_test, 1);
    const TemporalError e =
        temporal_error_net(p.test[0], p.test[1], p.reference[0], p.reference[1],
                           {&p.stddev[0], kSpp[0]}, {&p.stddev[1], kSpp[1]}, "noisy");
    ASSERT_TRUE(e.temporal_error_net.has_value());
    ASSERT_TRUE(e.reference_noise.has_value());
    const Expected plain = expected_temporal_error(sigma_test, true);
    const Expected net = expected_temporal_error(sigma_test, false);
    EXPECT_NEAR(e.temporal_error, plain.mean, plain.tolerance);
    EXPECT_NEAR(*e.temporal_error_net, net.mean, plain.tolerance);
    EXPECT_DOUBLE_EQ(*e.temporal_error_net, e.temporal_error - *e.reference_noise);
    // The subtracted share: (sigma_0^2 / spp_0 + sigma_1^2 / spp_1) mean(1 / (r_1^2 + 0.01)).
    const double both = kSigma[0] * kSigma[0] / kSpp[0] + kSigma[1] * kSigma[1] / kSpp[1];
    const double s0 = static_cast<float>(kSigma[0]);  // as the stddev images hold them
    const double s1 = static_cast<float>(kSigma[1]);
    const double share = (s0 * s0 / kSpp[0] + s1 * s1 / kSpp[1]) *
                         mean_inverse_denominator(p.reference[1], kNoiseSize);
    EXPECT_NEAR(*e.reference_noise, share, 1e-7 * share);
    EXPECT_NEAR(*e.reference_noise, both / (kMu[1] * kMu[1] + 0.01), 0.01 * share);
    // Without the noise the plain figure is the same and no net one is made.
    const TemporalError plain_only =
        temporal_error(p.test[0], p.test[1], p.reference[0], p.reference[1]);
    EXPECT_EQ(plain_only.temporal_error, e.temporal_error);
    EXPECT_FALSE(plain_only.temporal_error_net.has_value());
}

TEST(TemporalErrorNet, IsNearZeroForAnExactSequence) {
    const NoisyPair p = noisy_pair(0.0, 2);
    const TemporalError e =
        temporal_error_net(p.test[0], p.test[1], p.reference[0], p.reference[1],
                           {&p.stddev[0], kSpp[0]}, {&p.stddev[1], kSpp[1]}, "exact");
    const Expected plain = expected_temporal_error(0.0, true);
    EXPECT_NEAR(e.temporal_error, plain.mean, plain.tolerance);
    EXPECT_LT(std::fabs(*e.temporal_error_net), plain.tolerance);
    EXPECT_LT(plain.tolerance, 0.1 * plain.mean);
}

TEST(TemporalErrorNet, RefusesABadSampleCountOrStddevSize) {
    const NoisyPair p = noisy_pair(0.0, 3);
    const auto net = [&](ReferenceNoise a, ReferenceNoise b) {
        return temporal_error_net(p.test[0], p.test[1], p.reference[0], p.reference[1], a, b);
    };
    EXPECT_THROW(net({&p.stddev[0], 0.0}, {&p.stddev[1], kSpp[1]}), Error);
    EXPECT_THROW(net({&p.stddev[0], kSpp[0]}, {&p.stddev[1], -1.0}), Error);
    const Image small = rgb_image(2, 1);
    EXPECT_THROW(net({&small, kSpp[0]}, {&p.stddev[1], kSpp[1]}), Error);
    EXPECT_THROW(net({nullptr, kSpp[0]}, {&p.stddev[1], kSpp[1]}), Error);
}

// `radcache compare --frames` on files: reference frames ref####.exr with beauty, indirect and
// stddev layers (stddev constant kFileSigma) and frameFFFF-style records ref####.json with their
// spp; test frames test####.exr = reference + (-1)^f c on the beauty and + c on the indirect.
constexpr int kFrames = 4;
constexpr float kOffset = 0.125f;
constexpr float kFileSigma = 0.5f;
constexpr int kFileSpp = 64;

Image with_layers(const Image& beauty, const Image& indirect, float stddev) {
    const bool has_stddev = stddev > 0.0f;
    Image file(beauty.width, beauty.height, has_stddev ? 9 : 6);
    file.channel_names = {"R", "G", "B", "indirect.R", "indirect.G", "indirect.B"};
    if (has_stddev) {
        file.channel_names.insert(file.channel_names.end(), {"stddev.R", "stddev.G", "stddev.B"});
    }
    for (int y = 0; y < beauty.height; ++y) {
        for (int x = 0; x < beauty.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                file.at(x, y, c) = beauty.at(x, y, c);
                file.at(x, y, 3 + c) = indirect.at(x, y, c);
                if (has_stddev) {
                    file.at(x, y, 6 + c) = stddev;
                }
            }
        }
    }
    return file;
}

std::string frame_name(const char* stem, int frame, const char* extension = "exr") {
    char name[64];
    std::snprintf(name, sizeof name, "%s%04d.%s", stem, frame, extension);
    return name;
}

std::filesystem::path write_sequence(const std::string& name) {
    const auto dir = test::scratch_dir(name);
    for (int f = 0; f < kFrames; ++f) {
        const Image beauty = reference_frame(f);
        const Image indirect = reference_frame(10 + f);
        write_image(dir / frame_name("ref", f), with_layers(beauty, indirect, kFileSigma));
        write_file_atomically(dir / frame_name("ref", f, "json"),
                              "{\"spp\": " + std::to_string(kFileSpp) + "}\n");
        const float sign = f % 2 == 0 ? 1.0f : -1.0f;
        write_image(dir / frame_name("test", f),
                    with_layers(plus(beauty, sign * kOffset), plus(indirect, kOffset), 0.0f));
    }
    return dir;
}

test::CommandResult compare_frames(const std::filesystem::path& dir,
                                   std::vector<std::string> extra) {
    std::vector<std::string> args = {"compare",
                                     "--frames",
                                     "0:" + std::to_string(kFrames - 1),
                                     (dir / "test####.exr").string(),
                                     (dir / "ref####.exr").string(),
                                     "--json",
                                     (dir / "flicker.json").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::run_radcache(args);
}

TEST(CompareFrames, ReportsEveryFramesErrorAndTheTemporalError) {
    const auto dir = write_sequence("compare_frames");
    const test::CommandResult result = compare_frames(dir, {});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("temporal"), std::string::npos) << result.output;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "flicker.json"));
    ASSERT_EQ(j["frames"].size(), static_cast<size_t>(kFrames));
    EXPECT_EQ(j["first_frame"], 0);
    EXPECT_EQ(j["last_frame"], kFrames - 1);
    const double c2 = static_cast<double>(kOffset) * kOffset;
    const double variance = static_cast<double>(kFileSigma) * kFileSigma / kFileSpp;
    double relmse_sum = 0.0, temporal_sum = 0.0, temporal_net_sum = 0.0;
    for (int f = 0; f < kFrames; ++f) {
        SCOPED_TRACE(f);
        const nlohmann::json& row = j["frames"][f];
        const double inverse = mean_inverse_denominator(reference_frame(f));
        EXPECT_EQ(row["frame"], f);
        EXPECT_EQ(row["reference"], (dir / frame_name("ref", f)).string());
        EXPECT_NEAR(row["relmse"].get<double>(), c2 * inverse, 1e-9);
        EXPECT_NEAR(row["reference_noise"].get<double>(), variance * inverse, 1e-9);
        EXPECT_EQ(row["reference_spp"].get<double>(), kFileSpp);
        relmse_sum += c2 * inverse;
        if (f == 0) {
            EXPECT_TRUE(row["temporal_error"].is_null());
            EXPECT_TRUE(row["temporal_error_net"].is_null());
            continue;
        }
        // Off by 2c in every value; both frames' noise 2 sigma^2 / spp subtracted.
        EXPECT_NEAR(row["temporal_error"].get<double>(), 4.0 * c2 * inverse, 1e-9);
        EXPECT_NEAR(row["temporal_reference_noise"].get<double>(), 2.0 * variance * inverse, 1e-9);
        EXPECT_NEAR(row["temporal_error_net"].get<double>(), (4.0 * c2 - 2.0 * variance) * inverse,
                    1e-9);
        temporal_sum += 4.0 * c2 * inverse;
        temporal_net_sum += (4.0 * c2 - 2.0 * variance) * inverse;
    }
    EXPECT_NEAR(j["mean"]["relmse"].get<double>(), relmse_sum / kFrames, 1e-9);
    EXPECT_NEAR(j["mean"]["temporal_error"].get<double>(), temporal_sum / (kFrames - 1), 1e-9);
    EXPECT_NEAR(j["mean"]["temporal_error_net"].get<double>(), temporal_net_sum / (kFrames - 1),
                1e-9);

    // --aov indirect: a fixed offset, so every frame is off but nothing flickers; the stddev
    // layer describes the beauty, so no net figures.
    const test::CommandResult indirect = compare_frames(dir, {"--aov", "indirect"});
    ASSERT_EQ(indirect.exit_code, 0) << indirect.output;
    const nlohmann::json k = nlohmann::json::parse(read_file(dir / "flicker.json"));
    EXPECT_EQ(k["aov"], "indirect");
    EXPECT_EQ(k["mean"]["temporal_error"].get<double>(), 0.0);
    EXPECT_NEAR(k["frames"][2]["relmse"].get<double>(),
                c2 * mean_inverse_denominator(reference_frame(12)), 1e-9);
    EXPECT_TRUE(k["mean"]["temporal_error_net"].is_null());
    EXPECT_TRUE(k["frames"][1]["relmse_net"].is_null());

    // The sequence against itself.
    const test::CommandResult same = test::run_radcache(
        {"compare", "--frames", "1:3", (dir / "ref####.exr").string(),
         (dir / "ref####.exr").string(), "--json", (dir / "same.json").string()});
    ASSERT_EQ(same.exit_code, 0) << same.output;
    const nlohmann::json s = nlohmann::json::parse(read_file(dir / "same.json"));
    EXPECT_EQ(s["frames"].size(), 3u);
    EXPECT_EQ(s["mean"]["relmse"].get<double>(), 0.0);
    EXPECT_EQ(s["mean"]["temporal_error"].get<double>(), 0.0);
}

// One mask for every frame, or one per frame (####): a pair's temporal error is over the pixels
// both frames' masks select.
TEST(CompareFrames, TakesTheFiguresOverOneMaskOrAMaskPerFrame) {
    const auto dir = write_sequence("compare_frames_mask");
    Image left(kWidth, kHeight, 1);
    left.channel_names = {"Y"};
    Image all = left;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            left.at(x, y, 0) = x < kWidth / 2 ? 1.0f : 0.0f;
            all.at(x, y, 0) = 1.0f;
        }
    }
    write_image(dir / "left.exr", left);
    const test::CommandResult shared = compare_frames(dir, {"--mask", (dir / "left.exr").string()});
    ASSERT_EQ(shared.exit_code, 0) << shared.output;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "flicker.json"));
    const double c2 = static_cast<double>(kOffset) * kOffset;
    EXPECT_EQ(j["frames"][1]["pixels"], kWidth / 2 * kHeight);
    EXPECT_NEAR(j["frames"][1]["temporal_error"].get<double>(),
                4.0 * c2 * mean_inverse_denominator(reference_frame(1), kWidth / 2), 1e-9);
    // Per frame: all pixels but in frame 1 (the left half), so the pairs (0, 1) and (1, 2) are
    // over the left half and (2, 3) over every pixel.
    for (int f = 0; f < kFrames; ++f) {
        write_image(dir / frame_name("mask", f), f == 1 ? left : all);
    }
    const test::CommandResult per_frame =
        compare_frames(dir, {"--mask", (dir / "mask####.exr").string()});
    ASSERT_EQ(per_frame.exit_code, 0) << per_frame.output;
    const nlohmann::json k = nlohmann::json::parse(read_file(dir / "flicker.json"));
    EXPECT_EQ(k["frames"][0]["pixels"], kWidth * kHeight);
    EXPECT_EQ(k["frames"][1]["pixels"], kWidth / 2 * kHeight);
    EXPECT_EQ(k["frames"][1]["temporal_pixels"], kWidth / 2 * kHeight);
    EXPECT_EQ(k["frames"][2]["temporal_pixels"], kWidth / 2 * kHeight);
    EXPECT_EQ(k["frames"][3]["temporal_pixels"], kWidth * kHeight);
    EXPECT_NEAR(k["frames"][2]["temporal_error"].get<double>(),
                4.0 * c2 * mean_inverse_denominator(reference_frame(2), kWidth / 2), 1e-9);
}

// Bad command lines exit 2, bad or missing files 1; each with one line naming the problem and no
// JSON written.
TEST(CompareFrames, RefusesBadInputWithoutOutput) {
    const auto dir = write_sequence("compare_frames_bad");
    write_image(dir / frame_name("wide", 0),
                with_layers(reference_frame(0), reference_frame(0), 0));
    write_image(dir / frame_name("wide", 1), rgb_image(kWidth + 1, kHeight));
    const std::string test = (dir / "test####.exr").string();
    const std::string ref = (dir / "ref####.exr").string();
    const std::string json = (dir / "bad.json").string();
    struct Case {
        std::vector<std::string> args;
        int exit_code;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"--frames", "3:1", test, ref}, 2, "ends before it starts"},
        {{"--frames", "2:2", test, ref}, 2, "at least two frames"},
        {{"--frames", "a:b", test, ref}, 2, "expected A:B"},
        {{"--frames", "0:99999999999", test, ref},
         2,
         "frame 99999999999 outside [-2147483647, 2147483647]"},
        {{"--frames", "0:3", (dir / "test0000.exr").string(), ref}, 2, "has no ####"},
        {{"--frames", "0:3", test, (dir / "ref0000.exr").string()}, 2, "has no ####"},
        {{"--frames", "0:3", test, ref, "--error-image", (dir / "e.png").string()},
         2,
         "--error-image"},
        {{"--frames", "0:4", test, ref}, 1, "frame 4: no file " + (dir / "test0004.exr").string()},
        {{"--frames", "0:1", (dir / "wide####.exr").string(), ref}, 1, "17x8"},
        {{"--frames", "0:1", test, (dir / "wide####.exr").string()}, 1, "17x8"},
        {{"--frames", "0:3", test, ref, "--mask", (dir / "nomask####.exr").string()},
         1,
         "nomask0000.exr"},
        {{"--frames", "0:3", test, ref, "--aov", "direct"}, 2, "direct"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = {"compare"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        args.insert(args.end(), {"--json", json});
        const test::CommandResult result = test::run_radcache(args);
        SCOPED_TRACE(c.message);
        EXPECT_EQ(result.exit_code, c.exit_code) << result.output;
        EXPECT_NE(result.output.find(c.message), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(json));
    }
}

}  // namespace
}  // namespace rc
