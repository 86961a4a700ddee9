// Image error metrics (host/image/image_error.cpp) and `radcache compare` on images whose
// errors are worked out by hand.
#include "image/image_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

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

TEST(ImageError, MatchesHandComputedFigures) {
    const Image test = image_of({1, 2, 3, 0, 0, 0});
    const Image reference = image_of({1, 1, 1, 0, 0, 0.5f});
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
    const Image a = image_of({1, 2, 3, 0, 0, 0});
    Image wide(3, 1, 3);
    EXPECT_THROW(image_error(a, wide), Error);
    Image gray(2, 1, 1);
    EXPECT_THROW(image_error(a, gray), Error);
}

TEST(ImageError, CompareCommandReportsTheFigures) {
    const auto dir = test::scratch_dir("compare");
    write_image(dir / "test.exr", image_of({1, 2, 3, 0, 0, 0}));
    write_image(dir / "reference.exr", image_of({1, 1, 1, 0, 0, 0.5f}));
    const test::CommandResult result = test::run_radcache(
        {"compare", (dir / "test.exr").string(), (dir / "reference.exr").string(), "--json",
         (dir / "error.json").string()});
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
    const test::CommandResult layer =
        test::run_radcache({"compare", (dir / "test.exr").string(),
                            (dir / "reference.exr").string(), "--aov", "indirect"});
    EXPECT_EQ(layer.exit_code, 2);
    EXPECT_NE(layer.output.find("indirect"), std::string::npos) << layer.output;
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
    const auto dir = test::scratch_dir("compare_error_image");
    write_image(dir / "test.exr", image_of({1, 2, 3, 0, 0, 0}));
    write_image(dir / "reference.exr", image_of({1, 1, 1, 0, 0, 0.5f}));
    const test::CommandResult result = test::run_radcache(
        {"compare", (dir / "test.exr").string(), (dir / "reference.exr").string(), "--error-image",
         (dir / "error.exr").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image written = read_image(dir / "error.exr");
    const Image expected =
        error_image(image_of({1, 2, 3, 0, 0, 0}), image_of({1, 1, 1, 0, 0, 0.5f}));
    ASSERT_EQ(written.pixels.size(), expected.pixels.size());
    for (size_t i = 0; i < expected.pixels.size(); ++i) {
        EXPECT_EQ(written.pixels[i], expected.pixels[i]) << i;
    }
    const test::CommandResult refused = test::run_radcache(
        {"compare", (dir / "test.exr").string(), (dir / "reference.exr").string(), "--error-image",
         (dir / "error.tiff").string()});
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.output.find("error.tiff"), std::string::npos) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "error.tiff"));
}

}  // namespace
}  // namespace rc
