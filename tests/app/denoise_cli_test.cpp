// `radcache render --denoise` and `radcache merge --denoise` (docs/denoising.md) through the
// command line: the denoised beauty nearer the shipped 65 536-spp reference than the noisy one,
// the noisy beauty kept bitwise as a plain render's, a merge of crops denoised as the whole
// render, the denoiser's time taken out of --time, and the one-line refusals. Skipped, naming
// what was looked for, where Open Image Denoise is not installed.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "image/denoiser.h"
#include "image/image.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::string cornell() {
    return (test::source_dir() / "scenes" / "cornell-box" / "scene.json").string();
}

#define REQUIRE_DENOISER()                           \
    try {                                            \
        Denoiser::load("", denoise_quality("fast")); \
    } catch (const Error& e) {                       \
        GTEST_SKIP() << e.what();                    \
    }

// `radcache render` of the Cornell box at 64 x 64, 4 spp, the path tracer, into `out`.
test::CommandResult render(const std::filesystem::path& out, std::vector<std::string> options,
                           const std::vector<std::string>& environment = {}) {
    std::vector<std::string> args = {"render",   cornell(),  "-o",     out.string(), "--width",
                                     "64",       "--height", "64",     "--spp",      "4",
                                     "--method", "pt",       "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    return test::run_radcache(args, environment);
}

// The layer `name` (its three channels) of `image`.
Image layer(const Image& image, const std::string& name) { return select_layers(image, {name}); }

TEST(DenoiseCli, TheDenoisedBeautyIsNearerTheReferenceAndTheNoisyOneIsKept) {
    REQUIRE_DENOISER();
    const auto dir = test::scratch_dir("denoise_render");
    const test::CommandResult plain = render(dir / "plain.exr", {});
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    const test::CommandResult denoised = render(dir / "denoised.exr", {"--denoise"});
    ASSERT_EQ(denoised.exit_code, 0) << denoised.output;

    const Image noisy = layer(read_image(dir / "plain.exr"), "beauty");
    const Image both = read_image(dir / "denoised.exr");
    const Image kept = layer(both, "beauty_noisy");
    ASSERT_EQ(kept.pixels.size(), noisy.pixels.size());
    EXPECT_EQ(kept.pixels, noisy.pixels) << "beauty_noisy is not the plain render's beauty";

    const Image reference = test::cornell_reference("beauty", 64);
    const double before = image_error(noisy, reference).relmse;
    const double after = image_error(layer(both, "beauty"), reference).relmse;
    EXPECT_LT(after, before / 3.0) << "relMSE " << before << " noisy, " << after << " denoised";
}

TEST(DenoiseCli, AMergeOfCropsIsDenoisedAsTheWholeRender) {
    REQUIRE_DENOISER();
    const auto dir = test::scratch_dir("denoise_merge");
    ASSERT_EQ(render(dir / "whole.exr", {"--denoise"}).exit_code, 0);
    ASSERT_EQ(render(dir / "top.exr", {"--crop", "0:64,0:32"}).exit_code, 0);
    ASSERT_EQ(render(dir / "bottom.exr", {"--crop", "0:64,32:64"}).exit_code, 0);
    const test::CommandResult merged =
        test::run_radcache({"merge", "--quiet", "--denoise", (dir / "merged.exr").string(),
                            (dir / "top.exr").string(), (dir / "bottom.exr").string()});
    ASSERT_EQ(merged.exit_code, 0) << merged.output;
    const Image whole = read_image(dir / "whole.exr");
    const Image parts = read_image(dir / "merged.exr");
    EXPECT_EQ(parts.channel_names, whole.channel_names);
    EXPECT_EQ(parts.pixels, whole.pixels);
}

TEST(DenoiseCli, ItsTimeComesOutOfTheBudget) {
    REQUIRE_DENOISER();
    const auto dir = test::scratch_dir("denoise_time");
    const test::CommandResult result =
        test::run_radcache({"render", cornell(), "-o", (dir / "out.exr").string(), "--width", "64",
                            "--height", "64", "--method", "pt", "--time", "0.5", "--denoise",
                            "--quiet", "--stats", (dir / "stats.json").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    ASSERT_TRUE(stats.contains("denoise")) << stats.dump();
    EXPECT_GT(stats["denoise"]["predicted_seconds_per_frame"].get<double>(), 0.0);
    EXPECT_EQ(stats["denoise"]["quality"].get<std::string>(), "high");
    EXPECT_GT(stats["seconds"]["denoise"].get<double>(), 0.0);
}

// A refused render: exit `status`, its output naming `expected`, no image written.
void expect_refused(const std::vector<std::string>& options, int status,
                    const std::string& expected, const std::vector<std::string>& environment = {}) {
    const auto dir = test::scratch_dir("denoise_refused");
    const test::CommandResult result = render(dir / "out.exr", options, environment);
    EXPECT_EQ(result.exit_code, status) << result.output;
    EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(DenoiseCli, RefusesWhatItCannotDoInOneLine) {
    expect_refused({"--denoise-quality", "fast"}, 2, "--denoise");
    expect_refused({"--denoise", "--denoise-quality", "ultra"}, 2, "ultra");
    expect_refused({"--denoise", "--crop", "0:32,0:32"}, 2, "merge");
    expect_refused({"--denoise", "--denoise-library", "/nonexistent/libOIDN.so"}, 2,
                   "/nonexistent/libOIDN.so");
    expect_refused({"--denoise"}, 2, "/nonexistent/env.so",
                   {"RADCACHE_OIDN_LIBRARY=/nonexistent/env.so"});
}

TEST(DenoiseCli, RefusesAMethodWithoutTheLayersItReads) {
    REQUIRE_DENOISER();
    const auto dir = test::scratch_dir("denoise_normals");
    const test::CommandResult result =
        test::run_radcache({"render", cornell(), "-o", (dir / "out.exr").string(), "--width", "16",
                            "--height", "16", "--method", "normals", "--denoise", "--quiet"});
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("albedo"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace rc
