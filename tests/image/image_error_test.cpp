// Image error metrics (host/image/image_error.cpp) and `radcache compare` on images whose
// errors are worked out by hand.
#include "image/image_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "image/image_io.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

// Two 2 x 1 RGB images: test (1, 2, 3 | 0, 0, 0), reference (1, 1, 1 | 0, 0, 0.5).
// Differences 0, 1, 2 | 0, 0, -0.5: squared sum 5.25 over 6 values.
// relMSE terms: 0, 1 / 1.01, 4 / 1.01, 0, 0, 0.25 / 0.26.
Image image_of(std::vector<float> values) {
    Image image(2, 1, 3);
    image.channel_names = {"R", "G", "B"};
    image.pixels = std::move(values);
    return image;
}

Image test_image() { return image_of({1, 2, 3, 0, 0, 0}); }
Image reference_image() { return image_of({1, 1, 1, 0, 0, 0.5f}); }

// The scratch folder `name` holding test.exr (test_image()) and reference.exr (reference_image()),
// and `radcache compare` of the two.
struct CompareFiles {
    explicit CompareFiles(const std::string& name) : dir(test::scratch_dir(name)) {
        write_image(dir / "test.exr", test_image());
        write_image(dir / "reference.exr", reference_image());
    }
    // `radcache compare test.exr reference.exr` with `options`.
    test::CommandResult compare(const std::vector<std::string>& options) const {
        std::vector<std::string> args = {"compare", (dir / "test.exr").string(),
                                         (dir / "reference.exr").string()};
        args.insert(args.end(), options.begin(), options.end());
        return test::run_radcache(args);
    }
    const std::filesystem::path dir;
};

TEST(ImageError, MatchesHandComputedFigures) {
    const Image test = test_image();
    const Image reference = reference_image();
    const ImageError e = image_error(test, reference);
    const double mse = 5.25 / 6.0;
    EXPECT_NEAR(e.rmse, std::sqrt(mse), 1e-12);
    EXPECT_NEAR(e.relmse, (1.0 / 1.01 + 4.0 / 1.01 + 0.25 / 0.26) / 6.0, 1e-12);
    EXPECT_NEAR(e.psnr, -10.0 * std::log10(mse), 1e-9);
    EXPECT_NEAR(e.test_means[0], 0.5, 1e-12);
    EXPECT_NEAR(e.test_means[2], 1.5, 1e-12);
    EXPECT_NEAR(e.reference_means[2], 0.75, 1e-12);
    EXPECT_DOUBLE_EQ(e.max_error, 2.0);
    EXPECT_EQ(e.max_x, 0);
    EXPECT_EQ(e.max_channel, 2);
    const ImageError same = image_error(reference, reference);
    EXPECT_EQ(same.rmse, 0.0);
    EXPECT_TRUE(std::isinf(same.psnr));
}

TEST(ImageError, RefusesMismatchedImages) {
    const Image a = test_image();
    Image wide(3, 1, 3);
    EXPECT_THROW(image_error(a, wide), Error);
    Image gray(2, 1, 1);
    EXPECT_THROW(image_error(a, gray), Error);
}

TEST(ImageError, CompareCommandReportsTheFigures) {
    const CompareFiles files("compare");
    const std::filesystem::path& dir = files.dir;
    const test::CommandResult result = files.compare({"--json", (dir / "error.json").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("relmse"), std::string::npos) << result.output;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "error.json"));
    EXPECT_NEAR(j["rmse"].get<double>(), std::sqrt(5.25 / 6.0), 1e-6);
    EXPECT_NEAR(j["relmse"].get<double>(), (1.0 / 1.01 + 4.0 / 1.01 + 0.25 / 0.26) / 6.0, 1e-6);
    EXPECT_EQ(j["max_error"]["channel"], "B");

    write_image(dir / "wide.exr", Image(3, 1, 3));
    const test::CommandResult mismatch = test::run_radcache(
        {"compare", (dir / "wide.exr").string(), (dir / "reference.exr").string()});
    EXPECT_EQ(mismatch.exit_code, 1);
    EXPECT_NE(mismatch.output.find("3x1 against a 2x1 reference"), std::string::npos)
        << mismatch.output;
    const test::CommandResult layer = files.compare({"--aov", "indirect"});
    EXPECT_EQ(layer.exit_code, 2);
    EXPECT_NE(layer.output.find("indirect"), std::string::npos) << layer.output;
}

// A mask selecting the second pixel only: every figure is that pixel's (differences 0, 0, -0.5:
// squared sum 0.25 over 3 values; relMSE (0.25 / 0.26) / 3; means its own values); a mask that
// selects nothing, or of another size, is refused. Through the command too (--mask, --mask-aov).
TEST(ImageError, MaskTakesTheFiguresOverItsPixelsOnly) {
    const Image test = test_image();
    const Image reference = reference_image();
    Image mask(2, 1, 1);
    mask.pixels = {0.0f, 1.0f};
    const ImageError e = image_error(test, reference, "test", PixelMask{&mask});
    EXPECT_EQ(e.pixels, 1u);
    EXPECT_NEAR(e.rmse, std::sqrt(0.25 / 3.0), 1e-12);
    EXPECT_NEAR(e.relmse, 0.25 / 0.26 / 3.0, 1e-12);
    EXPECT_NEAR(e.test_means[0], 0.0, 1e-12);
    EXPECT_NEAR(e.reference_means[2], 0.5, 1e-12);
    EXPECT_EQ(e.max_x, 1);
    EXPECT_EQ(image_error(test, reference).pixels, 2u);
    Image none(2, 1, 1);
    EXPECT_THROW(image_error(test, reference, "test", PixelMask{&none}), Error);
    Image wide(3, 1, 1);
    EXPECT_THROW(image_error(test, reference, "test", PixelMask{&wide}), Error);

    const CompareFiles files("compare_mask");
    const std::filesystem::path& dir = files.dir;
    Image layered(2, 1, 4);
    layered.channel_names = {"R", "G", "B", "hits.Y"};
    layered.pixels = {1, 1, 1, 0, 0, 0, 0, 1};
    write_image(dir / "mask.exr", layered);
    const test::CommandResult result =
        files.compare({"--mask", (dir / "mask.exr").string(), "--mask-aov", "hits", "--json",
                       (dir / "e.json").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "e.json"));
    EXPECT_NEAR(j["relmse"].get<double>(), 0.25 / 0.26 / 3.0, 1e-6);
    EXPECT_EQ(j["pixels"].get<int>(), 1);
    const test::CommandResult first_layer =
        files.compare({"--mask", (dir / "mask.exr").string(), "--json", (dir / "f.json").string()});
    ASSERT_EQ(first_layer.exit_code, 0) << first_layer.output;
    EXPECT_EQ(nlohmann::json::parse(read_file(dir / "f.json"))["pixels"].get<int>(), 1);
    const test::CommandResult no_layer =
        files.compare({"--mask", (dir / "mask.exr").string(), "--mask-aov", "coverage"});
    EXPECT_EQ(no_layer.exit_code, 2);
    EXPECT_NE(no_layer.output.find("coverage"), std::string::npos) << no_layer.output;
    const test::CommandResult alone = files.compare({"--mask-aov", "hits"});
    EXPECT_EQ(alone.exit_code, 2);
}

// Synthetic images of known noise for the relMSE net of the reference's noise. Every value has
// mean mu; the reference's per-sample standard deviation is sigma_left on the left half and
// sigma_right on the right (so a per-pixel mix-up shows), its mean carries Gaussian noise of
// variance sigma^2 / spp, and the test image carries independent noise of variance
// sigma_test^2 (0: the exact mu).
struct NoisyImages {
    Image test;
    Image reference;
    Image stddev;
};

constexpr int kNoiseWidth = 256;
constexpr int kNoiseHeight = 256;
constexpr double kMu = 0.5;
constexpr double kSpp = 256.0;
constexpr double kSigmaLeft = 0.16;   // reference mean's standard deviation 0.01
constexpr double kSigmaRight = 0.32;  // 0.02

double sigma_at(int x) { return x < kNoiseWidth / 2 ? kSigmaLeft : kSigmaRight; }

NoisyImages noisy_images(double sigma_test, unsigned seed) {
    NoisyImages images{Image(kNoiseWidth, kNoiseHeight, 3), Image(kNoiseWidth, kNoiseHeight, 3),
                       Image(kNoiseWidth, kNoiseHeight, 3)};
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (int y = 0; y < kNoiseHeight; ++y) {
        for (int x = 0; x < kNoiseWidth; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double sigma = sigma_at(x);
                images.stddev.at(x, y, c) = static_cast<float>(sigma);
                images.reference.at(x, y, c) =
                    static_cast<float>(kMu + sigma / std::sqrt(kSpp) * normal(rng));
                images.test.at(x, y, c) = static_cast<float>(kMu + sigma_test * normal(rng));
            }
        }
    }
    return images;
}

// The expected relMSE, over D = mu^2 + 0.01, of values whose difference from the reference has
// variance s_i^2 = sigma_test^2 + (reference_share ? sigma_i^2 / spp : 0), with two bounds on how
// far a measurement may fall from it:
// - standard error: the relMSE is a mean over n values of squared Gaussians over D; a squared
//   N(0, s^2) has mean s^2 and variance 2 s^4, so the mean's variance is sum_i 2 s_i^4 / D^2 / n^2.
// - bias: image_error divides by r^2 + 0.01 with the noisy reference r = mu + e, not mu. With
//   f(r) = 1 / (r^2 + 0.01), f'' = -2 / x^2 + 8 mu^2 / x^3 (x = mu^2 + 0.01), and
//   E[e^2] = sigma_r^2, E[e^4] = 3 sigma_r^4, the second-order Taylor terms add
//   f'' sigma_r^2 (sigma_test^2 / 2 + 3 sigma_r^2 / 2) to the plain figure and
//   f'' sigma_r^2 (sigma_test^2 / 2 + sigma_r^2) to the net one; the first bounds both.
struct Expected {
    double mean = 0.0;
    double standard_error = 0.0;
    double bias_bound = 0.0;
    // A measurement within 5 standard errors and twice the second-order bias (covering the
    // higher orders, which are smaller by another factor sigma_r^2 f''/f < 1%).
    double tolerance() const { return 5.0 * standard_error + 2.0 * bias_bound; }
};

Expected expected_relmse(double sigma_test, bool reference_share) {
    const double x = kMu * kMu + 0.01;
    const double f2 = -2.0 / (x * x) + 8.0 * kMu * kMu / (x * x * x);
    const double n = 3.0 * kNoiseWidth * kNoiseHeight;
    const double column_values = 3.0 * kNoiseHeight;  // values sharing one column's variance
    Expected e;
    double variance = 0.0;
    for (int column = 0; column < kNoiseWidth; ++column) {
        const double reference_variance = sigma_at(column) * sigma_at(column) / kSpp;
        const double s2 = sigma_test * sigma_test + (reference_share ? reference_variance : 0.0);
        e.mean += column_values * s2 / x / n;
        variance += column_values * 2.0 * s2 * s2 / (x * x) / (n * n);
        e.bias_bound += column_values * std::fabs(f2) * reference_variance *
                        (0.5 * sigma_test * sigma_test + 1.5 * reference_variance) / n;
    }
    e.standard_error = std::sqrt(variance);
    return e;
}

TEST(ImageErrorNet, SubtractsTheReferencesExpectedNoise) {
    const double sigma_test = 0.02;
    const NoisyImages images = noisy_images(sigma_test, 1);
    const ImageError e =
        image_error_net(images.test, images.reference, images.stddev, kSpp, "noisy");
    ASSERT_TRUE(e.relmse_net.has_value());
    ASSERT_TRUE(e.reference_noise.has_value());
    // Plain relMSE: (sigma_test^2 + sigma^2 / spp) / (mu^2 + 0.01); net: sigma_test^2 / (...).
    const Expected plain = expected_relmse(sigma_test, true);
    const Expected net = expected_relmse(sigma_test, false);
    EXPECT_NEAR(e.relmse, plain.mean, plain.tolerance());
    // The net figure differs from the plain one by a near-constant, so it shares its spread.
    EXPECT_NEAR(*e.relmse_net, net.mean, plain.tolerance());
    EXPECT_DOUBLE_EQ(*e.relmse_net, e.relmse - *e.reference_noise);
    // The subtracted term by hand: mean of (sigma^2 / spp) / (r^2 + 0.01), one half per sigma.
    double noise = 0.0;
    for (int y = 0; y < kNoiseHeight; ++y) {
        for (int x = 0; x < kNoiseWidth; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double r = images.reference.at(x, y, c);
                noise += sigma_at(x) * sigma_at(x) / kSpp / (r * r + 0.01);
            }
        }
    }
    EXPECT_NEAR(*e.reference_noise, noise / (3.0 * kNoiseWidth * kNoiseHeight), 1e-9);
    // Without the reference's noise the plain figure is unchanged and no net figure is made.
    const ImageError plain_only = image_error(images.test, images.reference);
    EXPECT_EQ(plain_only.relmse, e.relmse);
    EXPECT_FALSE(plain_only.relmse_net.has_value());
}

TEST(ImageErrorNet, IsNearZeroForAnExactImage) {
    // test = mu exactly: all of relMSE is the reference's noise, and the net figure is within a
    // few standard errors of 0 (it may fall on either side; its sign is kept).
    const NoisyImages images = noisy_images(0.0, 2);
    const ImageError e =
        image_error_net(images.test, images.reference, images.stddev, kSpp, "exact");
    const Expected plain = expected_relmse(0.0, true);
    EXPECT_NEAR(e.relmse, plain.mean, plain.tolerance());
    EXPECT_LT(std::fabs(*e.relmse_net), plain.tolerance());
    // And that is small beside the plain figure, all of which is the reference's noise.
    EXPECT_LT(plain.tolerance(), 0.1 * plain.mean);
}

TEST(ImageErrorNet, RefusesABadSampleCountOrStddevSize) {
    const NoisyImages images = noisy_images(0.0, 3);
    EXPECT_THROW(image_error_net(images.test, images.reference, images.stddev, 0.0), Error);
    EXPECT_THROW(image_error_net(images.test, images.reference, images.stddev, -4.0), Error);
    EXPECT_THROW(image_error_net(images.test, images.reference, Image(2, 1, 3), kSpp), Error);
}

TEST(ErrorImage, MapsPerPixelRelMseOntoTheScale) {
    // Pixel 0: no error (black). Pixel 1: reference 0, test 1 -> relMSE 1 / 0.01 = 100, above
    // the top of the scale (white).
    const Image reference = image_of({0.5f, 0.5f, 0.5f, 0, 0, 0});
    const Image test = image_of({0.5f, 0.5f, 0.5f, 1, 1, 1});
    const Image errors = error_image(test, reference);
    ASSERT_EQ(errors.width, 2);
    ASSERT_EQ(errors.channels, 3);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(errors.at(0, 0, c), 0.0f);
        EXPECT_NEAR(errors.at(1, 0, c), 1.0f, 1e-6f);
    }
    // A pixel at relMSE 10^-2.5, the middle of the scale, gets the scale's middle colour
    // (sRGB-decoded): (v - r)^2 / (r^2 + 0.01) with r = 0 and v = sqrt(0.01 * 10^-2.5).
    const float v = static_cast<float>(std::sqrt(0.01 * std::pow(10.0, -2.5)));
    const Image middle = error_image(image_of({v, v, v, 0, 0, 0}), image_of({0, 0, 0, 0, 0, 0}));
    float srgb[3];
    error_scale_colour(0.5, srgb);
    for (int c = 0; c < 3; ++c) {
        const float linear =
            srgb[c] <= 0.04045f ? srgb[c] / 12.92f : std::pow((srgb[c] + 0.055f) / 1.055f, 2.4f);
        EXPECT_NEAR(middle.at(0, 0, c), linear, 1e-3f);
    }
    Image wide(3, 1, 3);
    EXPECT_THROW(error_image(test, wide), Error);
}

TEST(ErrorImage, ScaleLightnessRisesMonotonically) {
    double previous = -1.0;
    for (int i = 0; i <= 100; ++i) {
        float srgb[3];
        error_scale_colour(i / 100.0, srgb);
        const double lightness = 0.2126 * srgb[0] + 0.7152 * srgb[1] + 0.0722 * srgb[2];
        EXPECT_GT(lightness, previous) << "at t = " << i / 100.0;
        previous = lightness;
    }
}

TEST(ErrorImage, CompareCommandWritesItOrRefusesTheName) {
    const CompareFiles files("compare_error_image");
    const std::filesystem::path& dir = files.dir;
    const test::CommandResult result =
        files.compare({"--error-image", (dir / "error.exr").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image written = read_image(dir / "error.exr");
    const Image expected = error_image(test_image(), reference_image());
    ASSERT_EQ(written.pixels.size(), expected.pixels.size());
    for (size_t i = 0; i < expected.pixels.size(); ++i) {
        EXPECT_EQ(written.pixels[i], expected.pixels[i]) << i;
    }
    const test::CommandResult refused =
        files.compare({"--error-image", (dir / "error.tiff").string()});
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.output.find("error.tiff"), std::string::npos) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "error.tiff"));
}

}  // namespace
}  // namespace rc
