// Placement is bounded: a camera whose pixel is narrower than float precision can resolve ("fov":
// 1e-30) once made irradiance-record placement loop for ever (records of radius zero covered
// nothing, so every pass placed them again). Such a camera now renders, under every caching method
// that places records, the radiance the analytic scene gives; and the placement loop itself stops
// after kMaxPlacementPasses passes whatever its candidates do.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>

#include "image/image.h"
#include "image/image_io.h"
#include "methods/caching/placement_passes.h"
#include "test_support.h"

namespace rc {
namespace {

// A diffuse plane (reflectance 0.5) under a constant sky of radiance 1, seen from above by a
// camera of field of view 1e-30 degrees: every pixel sees the plane's centre, whose radiance is
// 0.5 (the sky's irradiance pi times rho / pi, nothing occluding it).
std::filesystem::path tiny_pixel_scene() {
    const auto dir = test::scratch_dir("placement_bound_scene");
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, 1],
                   "fov": 1e-30, "resolution": [4, 4]},
        "materials": {"ground": {"type": "diffuse", "reflectance": 0.5}},
        "shapes": [{"type": "rectangle", "material": "ground",
                    "transform": [{"scale": 5}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]}],
        "emitters": [{"type": "constant", "radiance": [1, 1, 1]}]
    })";
    return dir / "scene.json";
}

class TinyPixel : public testing::TestWithParam<std::string> {};

TEST_P(TinyPixel, RendersTheAnalyticRadiance) {
    const std::string method = GetParam();
    const auto out = test::scratch_dir("placement_bound_" + method) / "image.exr";
    const test::CommandResult result =
        test::run_radcache({"render", tiny_pixel_scene().string(), "--method", method, "--spp", "4",
                            "-o", out.string(), "-q", "--seed", "3"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image image = select_layers(read_image(out), {"beauty"});
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float v = image.at(x, y, c);
                ASSERT_TRUE(std::isfinite(v)) << method << " pixel " << x << "," << y;
                sum += v;
            }
        }
    }
    const double mean = sum / (3.0 * image.width * image.height);
    EXPECT_NEAR(mean, 0.5, 0.05) << method;
}

INSTANTIATE_TEST_SUITE_P(CachingMethods, TinyPixel, testing::Values("ic", "rc", "sdrc", "pt"));

// Candidates that no record ever covers: the loop stops at the bound and says how many are left.
TEST(PlacementPasses, StopAtTheBoundWhenNothingGetsCovered) {
    int passes = 0;
    int added = 0;
    const size_t left = run_placement_passes(
        true,
        [&]() {
            ++passes;
            UncoveredCandidates open;
            open.positions = {glm::vec3(0.0f), glm::vec3(10.0f)};
            open.normals = {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
            open.min_influence = {1.0f, 1.0f};
            return open;
        },
        [&](const std::vector<size_t>& chosen) { added += static_cast<int>(chosen.size()); });
    EXPECT_EQ(passes, kMaxPlacementPasses);
    EXPECT_EQ(added, 2 * (kMaxPlacementPasses - 1));
    EXPECT_EQ(left, 2u);
}

// Candidates a pass covers: the loop ends as soon as a pass finds none, with none left.
TEST(PlacementPasses, EndWhenEveryCandidateIsCovered) {
    std::vector<glm::vec3> open = {glm::vec3(0.0f), glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(10.0f)};
    int passes = 0;
    const size_t left = run_placement_passes(
        true,
        [&]() {
            ++passes;
            UncoveredCandidates found;
            found.positions = open;
            found.normals.assign(open.size(), glm::vec3(0.0f, 0.0f, 1.0f));
            found.min_influence.assign(open.size(), 1.0f);
            return found;
        },
        [&](const std::vector<size_t>& chosen) {
            // Thinning keeps the first of two candidates within 1 of each other; a record covers
            // what lies within 1 of it.
            EXPECT_EQ(chosen.size(), passes == 1 ? 2u : 0u);
            std::vector<glm::vec3> still;
            for (const glm::vec3& p : open) {
                bool covered = false;
                for (size_t c : chosen) {
                    covered = covered || glm::length(p - open[c]) <= 1.0f;
                }
                if (!covered) {
                    still.push_back(p);
                }
            }
            open = still;
        });
    EXPECT_EQ(passes, 2);
    EXPECT_EQ(left, 0u);
}

}  // namespace
}  // namespace rc
