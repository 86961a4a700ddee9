// Image files: EXR layers round-trip (float exactly, half within its precision), PNG encodes
// sRGB with exposure, and unsupported or unwritable outputs are refused before anything is
// written.
#include "image/image_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

Image layered_image() {
    Image image(3, 2, 6);
    image.channel_names = {"R", "G", "B", "indirect.R", "indirect.G", "indirect.B"};
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = 0.1f * static_cast<float>(i) + 1e-3f;
    }
    return image;
}

TEST(ImageIo, ExrKeepsEveryLayerExactly) {
    const auto dir = test::scratch_dir("image_exr");
    const Image image = layered_image();
    write_image(dir / "a.exr", image);
    const Image back = read_image(dir / "a.exr");
    ASSERT_EQ(back.channels, 6);
    EXPECT_EQ(back.channel_names, image.channel_names);
    EXPECT_EQ(back.pixels, image.pixels);
    ImageWriteOptions half;
    half.half = true;
    write_image(dir / "h.exr", image, half);
    const Image back_half = read_image(dir / "h.exr");
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        EXPECT_NEAR(back_half.pixels[i], image.pixels[i], image.pixels[i] * 1e-3f);
    }
    EXPECT_EQ(select_layers(back, {"indirect"}).pixels[0], image.pixels[3]);
    EXPECT_THROW(select_layers(back, {"albedo"}), Error);
}

TEST(ImageIo, PngIsExposedAndSrgbEncoded) {
    const auto dir = test::scratch_dir("image_png");
    Image image(2, 1, 3);
    image.pixels = {0.5f, 0.0f, 2.0f, 0.25f, 0.0031308f, 1.0f};
    write_image(dir / "a.png", image);
    const Image back = read_image(dir / "a.png");
    // sRGB(0.5) = 0.7354 -> 188 of 255; values above 1 clamp; 0 stays 0.
    EXPECT_NEAR(back.pixels[0] * 255.0f, 188.0f, 0.51f);
    EXPECT_EQ(back.pixels[1], 0.0f);
    EXPECT_EQ(back.pixels[2], 1.0f);
    EXPECT_NEAR(back.pixels[4] * 255.0f, 0.04045f * 255.0f, 0.51f);
    ImageWriteOptions brighter;
    brighter.exposure = 1.0f;  // 0.25 * 2 = 0.5
    write_image(dir / "b.png", image, brighter);
    EXPECT_NEAR(read_image(dir / "b.png").pixels[3] * 255.0f, 188.0f, 0.51f);
}

// PFM keeps the floats exactly; Radiance HDR (RGBE) shares one exponent per pixel, so each
// channel is exact to 1/128 of the pixel's largest.
TEST(ImageIo, HdrAndPfmKeepRgb) {
    const auto dir = test::scratch_dir("image_hdr");
    const Image image = layered_image();
    for (const char* name : {"a.hdr", "a.pfm"}) {
        write_image(dir / name, image);
        const Image back = read_image(dir / name);
        ASSERT_EQ(back.channels, 3) << name;
        ASSERT_EQ(back.width, 3) << name;
        for (int p = 0; p < 6; ++p) {
            const float largest =
                std::max({image.pixels[p * 6], image.pixels[p * 6 + 1], image.pixels[p * 6 + 2]});
            for (int c = 0; c < 3; ++c) {
                const float tolerance = std::string(name) == "a.pfm" ? 0.0f : largest / 128.0f;
                EXPECT_NEAR(back.pixels[p * 3 + c], image.pixels[p * 6 + c], tolerance) << name;
            }
        }
    }
}

TEST(ImageIo, BadOutputPathsAreRefused) {
    const auto dir = test::scratch_dir("image_bad");
    EXPECT_THROW(check_output_path(dir / "a.jpg"), Error);
    EXPECT_THROW(check_output_path(dir / "missing" / "a.png"), Error);
    EXPECT_THROW(check_output_path(dir), Error);
    EXPECT_NO_THROW(check_output_path(dir / "a.exr"));
    EXPECT_THROW(write_image(dir / "a.tiff", layered_image()), Error);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace rc
