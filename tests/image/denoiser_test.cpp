// The in-process denoiser (image/denoiser.h) on synthetic images whose clean picture is known:
// noise removed and the mean kept, the layers around the beauty untouched, the same image twice,
// non-finite input, and the one-line refusals (a missing layer, a library that cannot be
// loaded). Where Open Image Denoise is not installed (pip's pyoidn), the tests that filter are
// skipped, naming what was looked for.
#include "image/denoiser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "image/image_error.h"
#include "util/error.h"

namespace rc {
namespace {

// The denoiser as a render finds it, or the reason it cannot (the test is skipped with it).
std::unique_ptr<Denoiser> installed_denoiser(std::string* why) {
    try {
        return Denoiser::load("", denoise_quality("high"));
    } catch (const Error& e) {
        *why = e.what();
        return nullptr;
    }
}

#define REQUIRE_DENOISER(name)                                       \
    std::string why;                                                 \
    const std::unique_ptr<Denoiser> name = installed_denoiser(&why); \
    if (!name) {                                                     \
        GTEST_SKIP() << why;                                         \
    }

// A 96 x 96 render-like image: a clean beauty (a smooth ramp, and a darker square of another
// albedo), its albedo and normal layers, a `direct` layer after them, and the beauty with
// multiplicative noise of relative standard deviation `noise` (a fixed seed).
struct Synthetic {
    Image clean;
    Image noisy;
};

Synthetic synthetic(double noise) {
    const int size = 96;
    Synthetic s;
    s.noisy = Image(size, size, 12);
    s.noisy.channel_names = {"R",        "G",        "B",        "albedo.R",
                             "albedo.G", "albedo.B", "normal.R", "normal.G",
                             "normal.B", "direct.R", "direct.G", "direct.B"};
    s.clean = Image(size, size, 3);
    std::mt19937 random(7);
    std::normal_distribution<float> gauss(0.0f, static_cast<float>(noise));
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const bool square = x > 30 && x < 66 && y > 30 && y < 66;
            const float albedo = square ? 0.2f : 0.7f;
            const float light = 0.4f + 0.6f * static_cast<float>(x) / size;
            for (int c = 0; c < 3; ++c) {
                const float value = albedo * light * (c == 0 ? 1.0f : 0.8f);
                s.clean.at(x, y, c) = value;
                s.noisy.at(x, y, c) = std::max(0.0f, value * (1.0f + gauss(random)));
                s.noisy.at(x, y, 3 + c) = albedo;
                s.noisy.at(x, y, 6 + c) = c == 2 ? 1.0f : 0.0f;
                s.noisy.at(x, y, 9 + c) = 0.25f * c;
            }
        }
    }
    return s;
}

TEST(Denoiser, RemovesNoiseAndKeepsTheMean) {
    REQUIRE_DENOISER(denoiser);
    const Synthetic s = synthetic(0.5);
    const Image out = denoiser->denoise(s.noisy);
    const ImageError before = image_error(select_layers(s.noisy, {"beauty"}), s.clean);
    const ImageError after = image_error(select_layers(out, {"beauty"}), s.clean);
    // Relative noise 0.5 is a few samples per pixel; OIDN takes most of it away.
    EXPECT_LT(after.relmse, before.relmse / 10.0) << before.relmse << " -> " << after.relmse;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(after.test_means[c], after.reference_means[c], 0.03 * after.reference_means[c]);
    }
}

TEST(Denoiser, KeepsTheNoisyBeautyAndEveryOtherLayer) {
    REQUIRE_DENOISER(denoiser);
    const Synthetic s = synthetic(0.5);
    const Image out = denoiser->denoise(s.noisy);
    const std::vector<std::string> names = {
        "R",        "G",        "B",        "beauty_noisy.R", "beauty_noisy.G", "beauty_noisy.B",
        "albedo.R", "albedo.G", "albedo.B", "normal.R",       "normal.G",       "normal.B",
        "direct.R", "direct.G", "direct.B"};
    EXPECT_EQ(out.channel_names, names);
    const Image noisy = select_layers(out, {"beauty_noisy"});
    const Image others = select_layers(out, {"albedo", "normal", "direct"});
    EXPECT_EQ(noisy.pixels, select_layers(s.noisy, {"beauty"}).pixels);
    EXPECT_EQ(others.pixels, select_layers(s.noisy, {"albedo", "normal", "direct"}).pixels);
}

TEST(Denoiser, TheSameImageTwice) {
    REQUIRE_DENOISER(denoiser);
    const Synthetic s = synthetic(0.5);
    EXPECT_EQ(denoiser->denoise(s.noisy).pixels, denoiser->denoise(s.noisy).pixels);
}

TEST(Denoiser, NonFiniteInputGivesAFiniteImage) {
    REQUIRE_DENOISER(denoiser);
    Synthetic s = synthetic(0.2);
    s.noisy.at(10, 10, 0) = std::nanf("");
    s.noisy.at(50, 20, 1) = INFINITY;
    s.noisy.at(70, 70, 3) = std::nanf("");  // albedo
    const Image out = denoiser->denoise(s.noisy);
    const Image beauty = select_layers(out, {"beauty"});
    for (float v : beauty.pixels) {
        ASSERT_TRUE(std::isfinite(v));
    }
}

TEST(Denoiser, PredictsAPositiveTimeGrowingWithThePixels) {
    REQUIRE_DENOISER(denoiser);
    const double small = denoiser->predicted_seconds(64, 64);
    const double large = denoiser->predicted_seconds(1024, 1024);
    EXPECT_GT(small, 0.0);
    EXPECT_GE(large, small);
}

TEST(Denoiser, AMissingAuxiliaryLayerIsNamed) {
    REQUIRE_DENOISER(denoiser);
    const Synthetic s = synthetic(0.5);
    const Image without_normal = select_layers(s.noisy, {"beauty", "albedo", "direct"});
    try {
        denoiser->denoise(without_normal);
        FAIL() << "an image without a normal layer was denoised";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no normal layer"), std::string::npos) << e.what();
    }
}

TEST(Denoiser, ALibraryThatCannotBeLoadedIsNamed) {
    for (const std::string library : {"/nonexistent/libOpenImageDenoise.so.2", "libz.so.1"}) {
        try {
            Denoiser::load(library, denoise_quality("fast"));
            FAIL() << library << " loaded as Open Image Denoise";
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("--denoise-library " + library), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

TEST(Denoiser, AnUnknownQualityIsRefused) {
    EXPECT_NO_THROW(denoise_quality("balanced"));
    EXPECT_THROW(denoise_quality("ultra"), Error);
}

}  // namespace
}  // namespace rc
