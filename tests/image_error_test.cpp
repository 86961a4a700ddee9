// Image error metrics (host/image/image_error.cpp) and `radcache compare` on images whose
// errors are worked out by hand.
#include "image/image_error.h"

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace rc
