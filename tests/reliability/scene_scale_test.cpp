// Scale-relative tolerances: the Cornell box scaled uniformly (every shape's transform and the
// camera) renders the picture of the unscaled box, from 1e-15 to 1e9, where float allows; a
// scale whose extent single precision cannot intersect (1e-17) or whose coordinates leave the
// world range (1e10) is refused in one line naming the reason, with no image. Before, a scale of
// 1e-15 was refused ("emitter has zero area": the area's squared lengths underflowed), one of
// 1e-9 rendered 30% darker (a secondary ray's absolute offset near the origin, 1.5e-5, moved
// it across the room), one of 1e8 lost its direct light (the light's area overflowed float).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"

namespace rc {
namespace {

// The Cornell box with every shape scaled by `scale` about the origin, and the camera with it.
std::filesystem::path scaled_cornell_box(double scale, const std::string& name) {
    const std::filesystem::path box = test::source_dir() / "scenes" / "cornell-box";
    std::ifstream in(box / "scene.json");
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::json scene = nlohmann::json::parse(text.str(), nullptr, true, true);
    for (const char* key : {"position", "look_at"}) {
        for (nlohmann::json& value : scene["camera"][key]) {
            value = value.get<double>() * scale;
        }
    }
    for (nlohmann::json& shape : scene["shapes"]) {
        shape["file"] = (box / shape["file"].get<std::string>()).string();
        shape["transform"] = nlohmann::json::array({{{"scale", scale}}});
    }
    const std::filesystem::path path = test::scratch_dir("scene_scale_" + name) / "scene.json";
    std::ofstream(path) << scene.dump(1);
    return path;
}

// The beauty image of `scene` rendered with `method` at 32 x 32, `spp` samples, seed `seed`.
Image render(const std::filesystem::path& scene, const std::string& method, int spp, int seed) {
    const std::filesystem::path out =
        scene.parent_path() / (method + std::to_string(seed) + ".exr");
    const test::CommandResult result = test::run_radcache(
        {"render", scene.string(), "--method", method, "--width", "32", "--height", "32", "--spp",
         std::to_string(spp), "--seed", std::to_string(seed), "-o", out.string(), "-q"});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return select_layers(read_image(out), {"beauty"});
}

Image render_pt(const std::filesystem::path& scene, int seed) {
    return render(scene, "pt", 64, seed);
}

// The root mean square difference of two images of the same size over every pixel and channel.
double rmse(const Image& a, const Image& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    double squared = 0.0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double d = a.at(x, y, c) - b.at(x, y, c);
                squared += d * d;
            }
        }
    }
    return std::sqrt(squared / (3.0 * a.width * a.height));
}

// The unscaled box with seed 1, rendered once per test program.
const Image& unscaled() {
    static const Image image = render_pt(scaled_cornell_box(1.0, "1"), 1);
    return image;
}

class SceneScale : public testing::TestWithParam<double> {};

// With independent seeds, each channel's mean over the image equals the unscaled box's within 5
// standard errors of the difference (pixels are independent estimates); with the same seed the
// two renders draw the same random numbers, and differ only by float rounding.
TEST_P(SceneScale, RendersTheUnscaledPicture) {
    const double scale = GetParam();
    std::ostringstream name;
    name << scale;
    const std::filesystem::path scene = scaled_cornell_box(scale, name.str());
    const Image independent = render_pt(scene, 2);
    const Image same_seed = render_pt(scene, 1);
    const Image& reference = unscaled();
    ASSERT_EQ(independent.width, reference.width);
    const double n = static_cast<double>(reference.width) * reference.height;
    double squared_same = 0.0;
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        double sum2 = 0.0;
        for (int y = 0; y < reference.height; ++y) {
            for (int x = 0; x < reference.width; ++x) {
                const double d = independent.at(x, y, c) - reference.at(x, y, c);
                sum += d;
                sum2 += d * d;
                const double s = same_seed.at(x, y, c) - reference.at(x, y, c);
                squared_same += s * s;
            }
        }
        const double mean = sum / n;
        const double standard_error = std::sqrt((sum2 / n - mean * mean) / (n - 1.0));
        EXPECT_LT(std::fabs(mean), 5.0 * standard_error)
            << "scale " << scale << " channel " << c << ": mean difference " << mean;
    }
    // Measured at 7.9e-5 to 9.7e-5 for 1e-15 to 1e9; 5.5e-3 at 1e-6 before the fix.
    EXPECT_LT(std::sqrt(squared_same / (3.0 * n)), 2e-3) << "scale " << scale;
}

INSTANTIATE_TEST_SUITE_P(CornellBox, SceneScale,
                         testing::Values(1e-15, 1e-12, 1e-6, 1e-3, 1e3, 1e6, 1e9));

// The irradiance vector grid at small scales: with the same seed the scaled box draws the same
// photons and camera samples as the unscaled one, so its image differs by float rounding only.
// Before, the grid's deposit units (fixed-point units per unit of flux, about 1e11 over the
// brightest photon's flux) overflowed float at 1e-15, where the light carries 3e-31, and every
// crossing was dropped (RMSE 0.040); at 1e-12 the grid's extent had an absolute floor of 1e-9 and
// covered far more than the box (RMSE 3.6e-3).
class GridSceneScale : public testing::TestWithParam<double> {};

TEST_P(GridSceneScale, IvgRendersTheUnscaledPicture) {
    const double scale = GetParam();
    std::ostringstream name;
    name << "ivg_" << scale;
    static const Image reference = render(scaled_cornell_box(1.0, "ivg_1"), "ivg", 4, 7);
    const Image scaled = render(scaled_cornell_box(scale, name.str()), "ivg", 4, 7);
    EXPECT_LT(rmse(scaled, reference), 2e-3) << "scale " << scale;
}

INSTANTIATE_TEST_SUITE_P(CornellBox, GridSceneScale, testing::Values(1e-15, 1e-12, 1e-6));

// The decomposition where its near-field gather did not finish: the grid of its near triangles
// (a record grid) had an absolute thickness of 1e-6, far more than the box scaled by 3e-11, so its
// few cells listed thousands of the 115 k split triangles each (the gather took 11.7 s at 5e-11
// against 0.73 s unscaled, and did not finish at 3e-11). With the same seed the picture differs by
// rounding (measured RMSE 1e-5 at 3e-11, 1.6e-4 at 1e-11).
TEST(DecompositionSceneScale, RendersTheUnscaledPictureDownToItsLeastExtent) {
    const Image reference =
        render(scaled_cornell_box(1.0, "decomposition_1"), "decomposition", 4, 7);
    for (const double scale : {3e-11, 1e-11}) {
        std::ostringstream name;
        name << "decomposition_" << scale;
        const Image scaled = render(scaled_cornell_box(scale, name.str()), "decomposition", 4, 7);
        EXPECT_LT(rmse(scaled, reference), 2e-3) << "scale " << scale;
    }
}

// Below the least extent the decomposition renders (2^-27: by 1e-12 its image is off by RMSE
// 2.5e-3, by 1e-13 it drops non-finite samples) it refuses the scene in one line, with no image.
TEST(SceneScaleRefusal, TheDecompositionRefusesAnExtentBelowItsLeast) {
    const std::filesystem::path scene = scaled_cornell_box(1e-12, "decomposition_1e-12");
    const std::filesystem::path out = scene.parent_path() / "out.exr";
    const test::CommandResult result =
        test::run_radcache({"render", scene.string(), "--method", "decomposition", "--width", "8",
                            "--height", "8", "--spp", "1", "-o", out.string(), "-q"});
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("radcache: error: --method decomposition: the scene's extent"),
              std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find('\n'), result.output.size() - 1) << result.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// Outside what float can render: one error line naming the reason, exit 1, no image (at 1e10 the
// camera's warning that it stands outside the world range comes first).
TEST(SceneScaleRefusal, ScalesFloatCannotRenderAreRefusedInOneLine) {
    for (const auto& [scale, reason] :
         {std::pair<double, std::string>{1e-17, "the scene's extent"},
          std::pair<double, std::string>{1e10, "outside the world range"}}) {
        std::ostringstream name;
        name << "refused_" << scale;
        const std::filesystem::path scene = scaled_cornell_box(scale, name.str());
        const std::filesystem::path out = scene.parent_path() / "out.exr";
        const test::CommandResult result =
            test::run_radcache({"render", scene.string(), "--method", "pt", "--width", "8",
                                "--height", "8", "--spp", "1", "-o", out.string(), "-q"});
        EXPECT_EQ(result.exit_code, 1) << result.output;
        EXPECT_NE(result.output.find(reason), std::string::npos) << result.output;
        const size_t error = result.output.find("radcache: error:");
        ASSERT_NE(error, std::string::npos) << result.output;
        EXPECT_EQ(result.output.find('\n', error), result.output.size() - 1) << result.output;
        EXPECT_EQ(result.output.find("radcache: error:", error + 1), std::string::npos);
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

}  // namespace
}  // namespace rc
