// Pixel samplers (kernels/common/pixel_sampler.h, docs/pixel-filters.md "Pixel samplers"): the
// Sobol' sampler's first 2^k points in a pixel form a (0, k, 2)-net (checked against the net's
// definition, elementary interval by elementary interval); the independent sampler is the camera
// sample stream's first two words (computed here with the host's Philox); rendered edges converge
// faster under Sobol' than under independent samples and stay unbiased; bad names are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include "device/buffer.h"
#include "image/image_io.h"
#include "scene/camera.h"
#include "shared/rng.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

constexpr int kWidth = 100;

// The image positions the device draws for samples [0, count) of `pixel` (box filter 0.5).
std::vector<glm::vec2> device_positions(int sampler, unsigned pixel, unsigned count,
                                        uint64_t seed) {
    Context& context = test::shared_context();
    Camera camera;
    camera.sampler = sampler;
    const shared::CameraParams params = camera_params(camera, kWidth, kWidth);
    std::vector<unsigned> samples(count);
    for (unsigned s = 0; s < count; ++s) {
        samples[s] = s;
    }
    const Buffer<unsigned> pixels(context, std::vector<unsigned>(count, pixel), "pixels");
    const Buffer<unsigned> sample_buffer(context, samples, "samples");
    Buffer<glm::vec2> out(context, count, "positions");
    Kernel kernel = context.kernel("sampler_probe.cl", "sampler_position_probe");
    context.launch(kernel, count, params, static_cast<unsigned>(seed),
                   static_cast<unsigned>(seed >> 32), pixels, sample_buffer, out);
    return out.download();
}

// Whether the first 2^k offsets (in [0, 1)^2) put exactly one point in every elementary interval
// [i / 2^a, (i + 1) / 2^a) x [j / 2^(k - a), (j + 1) / 2^(k - a)), for every a in [0, k]: the
// definition of a (0, k, 2)-net in base 2 (Niederreiter 1992, Definition 4.1).
bool is_net(const std::vector<glm::vec2>& offsets, int k) {
    const size_t n = size_t{1} << k;
    for (int a = 0; a <= k; ++a) {
        std::vector<int> count(n, 0);
        for (size_t i = 0; i < n; ++i) {
            const size_t column = static_cast<size_t>(std::ldexp(offsets[i].x, a));
            const size_t row = static_cast<size_t>(std::ldexp(offsets[i].y, k - a));
            count[(column << (k - a)) + row] += 1;
        }
        for (int c : count) {
            if (c != 1) {
                return false;
            }
        }
    }
    return true;
}

// Sobol': in several pixels and seeds, every power-of-two prefix up to 256 points is a
// (0, k, 2)-net; the points of two pixels (and of two seeds) differ; independent samples are not
// nets (the test tells the samplers apart).
TEST(PixelSampler, SobolPrefixesAreNetsInEveryPixel) {
    const std::vector<unsigned> pixels = {0, 3 * kWidth + 7, 97 * kWidth + 83};
    std::vector<std::vector<glm::vec2>> seen;
    for (uint64_t seed : {uint64_t{0}, uint64_t{0x123456789abcULL}}) {
        for (unsigned pixel : pixels) {
            const std::vector<glm::vec2> positions =
                device_positions(RC_SAMPLER_SOBOL, pixel, 256, seed);
            std::vector<glm::vec2> offsets;
            for (const glm::vec2& p : positions) {
                offsets.emplace_back(p.x - static_cast<float>(pixel % kWidth),
                                     p.y - static_cast<float>(pixel / kWidth));
                ASSERT_GE(offsets.back().x, 0.0f);
                ASSERT_LT(offsets.back().x, 1.0f);
                ASSERT_GE(offsets.back().y, 0.0f);
                ASSERT_LT(offsets.back().y, 1.0f);
            }
            for (int k = 0; k <= 8; ++k) {
                EXPECT_TRUE(is_net(offsets, k))
                    << "pixel " << pixel << " seed " << seed << " k " << k;
            }
            for (const std::vector<glm::vec2>& other : seen) {
                EXPECT_NE(std::memcmp(other.data(), offsets.data(), 16 * sizeof(glm::vec2)), 0);
            }
            seen.push_back(offsets);
        }
    }
    const std::vector<glm::vec2> independent =
        device_positions(RC_SAMPLER_INDEPENDENT, pixels[1], 64, 0);
    std::vector<glm::vec2> offsets;
    for (const glm::vec2& p : independent) {
        offsets.emplace_back(p.x - 7.0f, p.y - 3.0f);
    }
    EXPECT_FALSE(is_net(offsets, 6));
}

// The independent sampler is the jitter every method drew before samplers: the first two words of
// the camera sample's stream (seed, pixel, s), as 24-bit fractions, added to the pixel's corner.
TEST(PixelSampler, IndependentIsTheSampleStreamsFirstTwoWords) {
    const uint64_t seed = 0xfeedf00d12ULL;
    const unsigned pixel = 41 * kWidth + 13;
    const std::vector<glm::vec2> positions =
        device_positions(RC_SAMPLER_INDEPENDENT, pixel, 512, seed);
    const auto lo = static_cast<unsigned>(seed);
    const auto hi = static_cast<unsigned>(seed >> 32);
    for (unsigned s = 0; s < positions.size(); ++s) {
        const float u =
            static_cast<float>(shared::rc_rng_word(lo, hi, pixel, s, 0) >> 8) / 16777216.0f;
        const float v =
            static_cast<float>(shared::rc_rng_word(lo, hi, pixel, s, 1) >> 8) / 16777216.0f;
        const float x = 13.0f + u;
        const float y = 41.0f + v;
        ASSERT_EQ(std::memcmp(&positions[s].x, &x, sizeof x), 0) << s;
        ASSERT_EQ(std::memcmp(&positions[s].y, &y, sizeof y), 0) << s;
    }
}

// An emissive rectangle over black seen head-on (16 x 12 pixels, emitters seen directly only): a
// pixel's exact value under the box filter is the fraction of its square the rectangle covers.
constexpr const char* kEdgeScene = R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0],
    "fov": 40, "resolution": [16, 12]},
    "shapes": [{"type": "rectangle", "emitter": {"type": "area", "radiance": 1},
                "transform": [{"scale": [0.63, 0.41, 1]}, {"translate": [0.137, -0.093, 0]}]}],
    "render": {"max_depth": 0}})";

double covered(int px, int py) {
    const double tangent = std::tan(20.0 * M_PI / 180.0);
    const auto image_x = [&](double x) { return 8.0 * (1.0 + x / (4.0 * tangent)); };
    const auto image_y = [&](double y) { return 6.0 - y * 8.0 / (4.0 * tangent); };
    const auto overlap = [](double a, double b, double lo) {
        return std::max(0.0, std::min(b, lo + 1.0) - std::max(a, lo));
    };
    return overlap(image_x(0.137 - 0.63), image_x(0.137 + 0.63), px) *
           overlap(image_y(-0.093 + 0.41), image_y(-0.093 - 0.41), py);
}

// The squared error of the rectangle's image against its exact coverage, summed over the pixels,
// at `spp` samples per pixel under `sampler`, for seeds 0..seeds-1 (summed too).
double edge_error(const std::string& sampler, int spp, int seeds) {
    const auto dir = test::scratch_dir("pixel_sampler_edges");
    write_file_atomically(dir / "edge.json", kEdgeScene);
    double error = 0.0;
    for (int seed = 0; seed < seeds; ++seed) {
        const auto out = dir / ("edge_" + sampler + ".pfm");
        const test::CommandResult result = test::run_radcache(
            {"render", (dir / "edge.json").string(), "-o", out.string(), "--spp",
             std::to_string(spp), "--seed", std::to_string(seed), "--sampler", sampler, "--quiet"});
        EXPECT_EQ(result.exit_code, 0) << result.output;
        const Image image = read_image(out);
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const double d = image.at(x, y, 0) - covered(x, y);
                error += d * d;
            }
        }
    }
    return error;
}

// At 64 samples per pixel the edge pixels' squared error under Sobol' is well below a quarter of
// the independent samples' (measured ratio about 40 on this scene; independent: the binomial
// p (1 - p) / 64 per pixel); and from 16 to 256 samples Sobol's error falls by more than the 16x
// independent samples give (a rate above 1/N in squared error).
TEST(PixelSampler, SobolEdgesConvergeFasterThanIndependentSamples) {
    double binomial = 0.0;
    for (int y = 0; y < 12; ++y) {
        for (int x = 0; x < 16; ++x) {
            binomial += covered(x, y) * (1.0 - covered(x, y)) / 64.0;
        }
    }
    ASSERT_GT(binomial, 0.05);  // enough edge pixels
    const double independent = edge_error("independent", 64, 4) / 4;
    const double sobol = edge_error("sobol", 64, 4) / 4;
    EXPECT_NEAR(independent, binomial, 0.5 * binomial);
    EXPECT_LT(sobol, 0.25 * independent) << "independent " << independent;
    EXPECT_GT(edge_error("sobol", 16, 4), 16.0 * edge_error("sobol", 256, 4));
}

// --sampler and camera.sampler: read, reported in the stats, and refused by name when unknown.
TEST(PixelSampler, SamplerIsReadReportedAndChecked) {
    const auto dir = test::scratch_dir("pixel_sampler_names");
    const auto render = [&](const std::string& camera_extra, std::vector<std::string> extra) {
        write_file_atomically(dir / "s.json",
                              R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0],
            "fov": 40, "resolution": [8, 6])" +
                                  camera_extra + R"(}, "shapes": [{"type": "rectangle"}]})");
        std::vector<std::string> args = {
            "render",  (dir / "s.json").string(),    "-o", (dir / "out.pfm").string(), "--quiet",
            "--stats", (dir / "stats.json").string()};
        args.insert(args.end(), extra.begin(), extra.end());
        return test::run_radcache(args);
    };
    const auto sampler_in_stats = [&] {
        return nlohmann::json::parse(read_file(dir / "stats.json"))["sampler"].get<std::string>();
    };
    ASSERT_EQ(render("", {}).exit_code, 0);
    EXPECT_EQ(sampler_in_stats(), "sobol");
    ASSERT_EQ(render(R"(, "sampler": "independent")", {}).exit_code, 0);
    EXPECT_EQ(sampler_in_stats(), "independent");
    ASSERT_EQ(render(R"(, "sampler": "independent")", {"--sampler", "sobol"}).exit_code, 0);
    EXPECT_EQ(sampler_in_stats(), "sobol");
    std::filesystem::remove(dir / "out.pfm");
    test::CommandResult bad = render("", {"--sampler", "halton"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("--sampler"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("halton"), std::string::npos) << bad.output;
    bad = render(R"(, "sampler": "stratified")", {});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.output.find("camera.sampler"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.pfm"));
}

}  // namespace
}  // namespace rc
