// Pixel reconstruction filters (kernels/common/pixel_filter.h, docs/pixel-filters.md): the
// offsets camera samples are drawn with follow each filter (against its integral computed here);
// rendered edges match the filter-weighted integral of the image computed on the host; a constant
// image stays constant under every method; the image's total is kept; the box of radius 0.5 is
// the jitter of before; results do not depend on --max-chunk and --local-size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>
#include <random>

#include "device/buffer.h"
#include "image/image_io.h"
#include "methods/registry.h"
#include "scene/camera.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

// The filters' 1D profiles as docs/pixel-filters.md defines them (not normalized).
double filter_profile(int type, double radius, double t) {
    if (std::abs(t) > radius) {
        return 0.0;
    }
    switch (type) {
        case RC_FILTER_TENT:
            return radius - std::abs(t);
        case RC_FILTER_GAUSSIAN: {
            const double sigma = radius / 3.0;
            return std::exp(-t * t / (2 * sigma * sigma)) -
                   std::exp(-radius * radius / (2 * sigma * sigma));
        }
        default:
            return 1.0;
    }
}

// The integral of the normalized profile over [a, b] (midpoint rule, 20000 steps over the
// support).
double filter_mass(int type, double radius, double a, double b) {
    const int steps = 20000;
    const double h = 2 * radius / steps;
    double inside = 0.0;
    double total = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double t = -radius + (i + 0.5) * h;
        const double f = filter_profile(type, radius, t);
        total += f;
        if (t > a && t < b) {
            inside += f;
        }
    }
    return inside / total;
}

struct FilterCase {
    int type;
    float radius;
};

const std::vector<FilterCase> kFilters = {{RC_FILTER_BOX, 0.5f},      {RC_FILTER_BOX, 1.3f},
                                          {RC_FILTER_TENT, 1.0f},     {RC_FILTER_TENT, 2.0f},
                                          {RC_FILTER_GAUSSIAN, 1.5f}, {RC_FILTER_GAUSSIAN, 0.8f}};

// Positions the device draws for pixel `pixel` of a 100-pixel-wide image with the given uvs.
std::vector<glm::vec2> device_positions(FilterCase filter, unsigned pixel,
                                        const std::vector<glm::vec2>& uvs) {
    Context& context = test::shared_context();
    Camera camera;
    camera.filter = {filter.type, filter.radius};
    const shared::CameraParams params = camera_params(camera, 100, 100);
    const Buffer<unsigned> pixels(context, std::vector<unsigned>(uvs.size(), pixel), "pixels");
    const Buffer<glm::vec2> uv_buffer(context, uvs, "uvs");
    Buffer<glm::vec2> out(context, uvs.size(), "positions");
    Kernel kernel = context.kernel("filter_probe.cl", "filter_position_probe");
    context.launch(kernel, uvs.size(), params, pixels, uv_buffer, out);
    return out.download();
}

// A sample's offsets fill the filter's support and distribute as the normalized filter: the
// stratified fractions of 8192 samples in each of 16 bins against the filter's mass there, which
// sums to 1 (one sample's footprint integrates to 1, all of it in its own pixel).
TEST(PixelFilter, SampleOffsetsFollowTheNormalizedFilter) {
    const int n = 8192;
    const int bins = 16;
    std::vector<glm::vec2> uvs;
    for (int i = 0; i < n; ++i) {
        const float u = (static_cast<float>(i) + 0.5f) / n;
        uvs.emplace_back(u, 1.0f - u);
    }
    const unsigned pixel = 3 * 100 + 7;  // (7, 3): centre (7.5, 3.5)
    for (const FilterCase& filter : kFilters) {
        const std::vector<glm::vec2> positions = device_positions(filter, pixel, uvs);
        std::vector<double> fraction(bins, 0.0);
        for (const glm::vec2& p : positions) {
            const double dx = p.x - 7.5;
            const double dy = p.y - 3.5;
            ASSERT_LE(std::abs(dx), filter.radius * (1 + 1e-5)) << filter.type;
            ASSERT_LE(std::abs(dy), filter.radius * (1 + 1e-5)) << filter.type;
            const int bin = std::clamp(
                static_cast<int>((dx + filter.radius) / (2 * filter.radius) * bins), 0, bins - 1);
            fraction[bin] += 1.0 / n;
        }
        double mass_total = 0.0;
        for (int b = 0; b < bins; ++b) {
            const double a = -filter.radius + 2.0 * filter.radius * b / bins;
            const double mass =
                filter_mass(filter.type, filter.radius, a, a + 2.0 * filter.radius / bins);
            mass_total += mass;
            EXPECT_NEAR(fraction[b], mass, 1.5e-3)
                << pixel_filter_name(filter.type) << " radius " << filter.radius << " bin " << b;
        }
        EXPECT_NEAR(mass_total, 1.0, 1e-9);
    }
}

// The box filter of radius 0.5 places a sample at (x + u, y + v) bitwise: the jitter every method
// drew before filters existed, so default images are unchanged.
TEST(PixelFilter, DefaultBoxIsThePixelJitterBitwise) {
    std::mt19937 random(7);
    std::vector<glm::vec2> uvs;
    for (int i = 0; i < 4096; ++i) {
        // rc_uint_to_unit_float's values: multiples of 2^-24 in [0, 1).
        uvs.emplace_back(static_cast<float>(random() >> 8) * (1.0f / 16777216.0f),
                         static_cast<float>(random() >> 8) * (1.0f / 16777216.0f));
    }
    const unsigned pixel = 97 * 100 + 83;
    const std::vector<glm::vec2> positions = device_positions({RC_FILTER_BOX, 0.5f}, pixel, uvs);
    for (size_t i = 0; i < uvs.size(); ++i) {
        const float x = 83.0f + uvs[i].x;
        const float y = 97.0f + uvs[i].y;
        ASSERT_EQ(std::memcmp(&positions[i].x, &x, sizeof x), 0) << i << ": " << positions[i].x;
        ASSERT_EQ(std::memcmp(&positions[i].y, &y, sizeof y), 0) << i << ": " << positions[i].y;
    }
}

// An emissive rectangle (radiance 1) over black, seen head-on: 16 x 12 pixels, only emitters seen
// directly. Its image is the indicator of a rectangle in image coordinates, so a pixel's expected
// value under a separable filter is the product of the filter's mass over the rectangle's extent
// along x and along y.
struct EdgeScene {
    static constexpr int kWidth = 16;
    static constexpr int kHeight = 12;
    static constexpr double kDistance = 4.0;
    static constexpr double kFov = 40.0;
    // The rectangle [-1, 1]^2 scaled by (sx, sy) and moved by (tx, ty).
    static constexpr double kSx = 0.63, kSy = 0.41, kTx = 0.137, kTy = -0.093;

    static std::string json() {
        return R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 40,
                   "resolution": [16, 12]},
                   "shapes": [{"type": "rectangle", "emitter": {"type": "area", "radiance": 1},
                               "transform": [{"scale": [0.63, 0.41, 1]},
                                             {"translate": [0.137, -0.093, 0]}]}],
                   "render": {"max_depth": 0}})";
    }

    // Image x of world x (and image y of world y) on the plane z = 0.
    static double image_x(double x) {
        const double tangent = std::tan(kFov * 0.5 * M_PI / 180.0);
        return kWidth * 0.5 * (1.0 + x / (kDistance * tangent));
    }
    static double image_y(double y) {
        const double tangent = std::tan(kFov * 0.5 * M_PI / 180.0);
        return kHeight * 0.5 - y * kWidth * 0.5 / (kDistance * tangent);
    }

    static double expected(int type, double radius, int px, int py) {
        const double x0 = image_x(kTx - kSx), x1 = image_x(kTx + kSx);
        const double y0 = image_y(kTy + kSy), y1 = image_y(kTy - kSy);
        const double cx = px + 0.5, cy = py + 0.5;
        return filter_mass(type, radius, x0 - cx, x1 - cx) *
               filter_mass(type, radius, y0 - cy, y1 - cy);
    }

    // The rectangle's area in pixels.
    static double area() {
        return (image_x(kTx + kSx) - image_x(kTx - kSx)) *
               (image_y(kTy - kSy) - image_y(kTy + kSy));
    }
};

Image render_edges(const std::filesystem::path& dir, const std::string& filter,
                   const std::string& radius, int spp) {
    write_file_atomically(dir / "edge.json", EdgeScene::json());
    const auto out = dir / ("edge_" + filter + "_" + radius + ".exr");
    const test::CommandResult result = test::run_radcache(
        {"render", (dir / "edge.json").string(), "-o", out.string(), "--spp", std::to_string(spp),
         "--filter", filter, "--filter-radius", radius, "--quiet", "--aovs", "beauty"});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_image(out);
}

// Each filter's render of the rectangle's edges against the host's filter-weighted integral,
// within 5 standard deviations of the pixel's mean of 0/1 samples; the box-filtered render fails
// the tent's reference (the test tells the filters apart); and the image's total is the
// rectangle's area (filters neither add nor lose light).
TEST(PixelFilter, EdgesMatchTheHostFilterIntegral) {
    const auto dir = test::scratch_dir("pixel_filter_edges");
    const int spp = 2048;
    struct Case {
        std::string name;
        int type;
        double radius;
        std::string radius_text;
    };
    const std::vector<Case> cases = {{"box", RC_FILTER_BOX, 0.5, "0.5"},
                                     {"tent", RC_FILTER_TENT, 1.0, "1"},
                                     {"tent", RC_FILTER_TENT, 1.7, "1.7"},
                                     {"gaussian", RC_FILTER_GAUSSIAN, 1.5, "1.5"}};
    std::vector<Image> images;
    for (const Case& c : cases) {
        const Image image = render_edges(dir, c.name, c.radius_text, spp);
        ASSERT_EQ(image.width, EdgeScene::kWidth);
        ASSERT_EQ(image.height, EdgeScene::kHeight);
        double total = 0.0;
        int partial = 0;  // pixels the edges cross
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const double p = EdgeScene::expected(c.type, c.radius, x, y);
                const double sigma = std::sqrt(p * (1 - p) / spp);
                EXPECT_NEAR(image.at(x, y, 0), p, 5 * sigma + 2e-4)
                    << c.name << " " << c.radius << " pixel " << x << ", " << y;
                EXPECT_EQ(image.at(x, y, 0), image.at(x, y, 1));
                total += image.at(x, y, 0);
                partial += p > 0.01 && p < 0.99;
            }
        }
        EXPECT_GE(partial, 20) << c.name;
        // Every pixel's samples are independent: the total's standard deviation is at most
        // sqrt(pixels / (4 spp)).
        EXPECT_NEAR(total, EdgeScene::area(), 5 * std::sqrt(192.0 / (4 * spp))) << c.name;
        images.push_back(image);
    }
    int failing = 0;
    for (int y = 0; y < EdgeScene::kHeight; ++y) {
        for (int x = 0; x < EdgeScene::kWidth; ++x) {
            const double p = EdgeScene::expected(RC_FILTER_TENT, 1.0, x, y);
            failing +=
                std::abs(images[0].at(x, y, 0) - p) > 5 * std::sqrt(p * (1 - p) / spp) + 2e-4;
        }
    }
    EXPECT_GE(failing, 10) << "the box's image should fail the tent's reference at the edges";
}

// A scene seen only as a constant environment renders that constant in every pixel under every
// filter and every method whose image is radiance.
TEST(PixelFilter, ConstantImageStaysConstantUnderEveryMethodAndFilter) {
    const auto dir = test::scratch_dir("pixel_filter_constant");
    write_file_atomically(dir / "sky.json", R"({
        "camera": {"position": [0, 0, 0], "look_at": [0, 0, -1], "fov": 60, "resolution": [8, 6]},
        "shapes": [{"type": "rectangle", "transform": [{"translate": [0, 0, 5]}]}],
        "emitters": [{"type": "constant", "radiance": [0.25, 0.5, 0.75]}]})");
    for (const MethodEntry& entry : method_registry()) {
        if (entry.beauty != Beauty::kRadiance) {
            continue;
        }
        const std::string& method = entry.name;
        for (const std::string filter : {"box", "tent", "gaussian"}) {
            const auto out = dir / (method + "_" + filter + ".pfm");
            const test::CommandResult result = test::run_radcache(
                {"render", (dir / "sky.json").string(), "-o", out.string(), "--method", method,
                 "--filter", filter, "--filter-radius", "2", "--spp", "4", "--quiet"});
            ASSERT_EQ(result.exit_code, 0) << method << " " << filter << ": " << result.output;
            const Image image = read_image(out);
            for (int y = 0; y < image.height; ++y) {
                for (int x = 0; x < image.width; ++x) {
                    EXPECT_FLOAT_EQ(image.at(x, y, 0), 0.25f) << method << " " << filter;
                    EXPECT_FLOAT_EQ(image.at(x, y, 1), 0.5f) << method << " " << filter;
                    EXPECT_FLOAT_EQ(image.at(x, y, 2), 0.75f) << method << " " << filter;
                }
            }
        }
    }
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// Filtered images are bitwise identical whatever the chunking and the work-group size, and differ
// from the box's; the stats name the filter.
TEST(PixelFilter, FilteredImagesDoNotDependOnChunksOrWorkGroups) {
    const auto dir = test::scratch_dir("pixel_filter_determinism");
    const std::string scene = (test::source_dir() / "scenes/cornell-box/scene.json").string();
    for (const std::string method : {"pt", "ic"}) {
        const auto render = [&](const std::string& filter, const std::vector<std::string>& extra) {
            const auto out = dir / (method + filter + std::to_string(extra.size()) + ".exr");
            std::vector<std::string> args = {"render",
                                             scene,
                                             "-o",
                                             out.string(),
                                             "--method",
                                             method,
                                             "--filter",
                                             filter,
                                             "--width",
                                             "32",
                                             "--height",
                                             "24",
                                             "--spp",
                                             "2",
                                             "--quiet",
                                             "--stats",
                                             (dir / "stats.json").string()};
            if (method == "ic") {
                args.insert(args.end(), {"--ic-rays", "64"});
            }
            args.insert(args.end(), extra.begin(), extra.end());
            const test::CommandResult result = test::run_radcache(args);
            EXPECT_EQ(result.exit_code, 0) << result.output;
            return read_image(out);
        };
        for (const std::string filter : {"tent", "gaussian"}) {
            const Image plain = render(filter, {});
            const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
            EXPECT_EQ(stats["filter"]["type"], filter);
            EXPECT_FALSE(same_pixels(plain, render("box", {})));
            EXPECT_TRUE(
                same_pixels(plain, render(filter, {"--max-chunk", "333", "--local-size", "8"})))
                << method << " " << filter;
        }
    }
}

// A scene's camera may name its filter; a bad one is refused naming the key.
TEST(PixelFilter, SceneCameraFilterIsReadAndChecked) {
    const auto dir = test::scratch_dir("pixel_filter_scene");
    const auto scene = [&](const std::string& filter) {
        const std::string json = R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0],
            "fov": 40, "resolution": [16, 12], "filter": )" +
                                 filter + R"(}, "shapes": [{"type": "rectangle"}]})";
        write_file_atomically(dir / "s.json", json);
        return test::run_radcache({"render", (dir / "s.json").string(), "-o",
                                   (dir / "out.pfm").string(), "--spp", "1", "--quiet", "--stats",
                                   (dir / "stats.json").string()});
    };
    ASSERT_EQ(scene(R"({"type": "gaussian"})").exit_code, 0);
    nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    EXPECT_EQ(stats["filter"]["type"], "gaussian");
    EXPECT_FLOAT_EQ(stats["filter"]["radius"].get<float>(), 1.5f);
    std::filesystem::remove(dir / "out.pfm");
    std::filesystem::remove(dir / "stats.json");
    test::CommandResult bad = scene(R"({"type": "lanczos"})");
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.output.find("camera.filter.type"), std::string::npos) << bad.output;
    bad = scene(R"({"type": "tent", "radius": 0})");
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.output.find("camera.filter.radius"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.pfm"));
}

}  // namespace
}  // namespace rc
