// Frames of an animation differ where the animation says they should, and only there. The oracle is
// the scene file itself: the moving sphere's centre at a frame is evaluated here from its track's
// keyframes (linear translation between keyframes, docs/scene-format.md "Animation"), projected
// with the scene's pinhole camera (docs/scene-format.md "camera"), and compared with what
// `radcache render --frames F:F` draws. Only the command line is used.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

constexpr int kSize = 64;              // rendered width and height
constexpr int kFrames[2] = {5, 17};    // between the keyframes 0 and 23
constexpr double kMarginPixels = 2.0;  // pixel filter, jitter and tessellation
constexpr double kSigmas = 5.0;        // noise bound of a mean, in standard errors
constexpr const char* kBall = "shape:ball";

std::filesystem::path scene_path() {
    return test::source_dir() / "scenes/moving-sphere/scene.json";
}

glm::dvec3 vec3_of(const nlohmann::json& v) {
    return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

// The pinhole camera of docs/scene-format.md: fov spans the image's x extent; image x grows along
// cross(forward, up), image y downwards; a pixel's ray passes through its centre.
struct Pinhole {
    glm::dvec3 eye, forward, right, up;
    double tangent = 0.0;  // tan(fov / 2)

    glm::dvec3 ray(int x, int y) const {
        const double u = (2.0 * (x + 0.5) / kSize - 1.0) * tangent;
        const double v = (1.0 - 2.0 * (y + 0.5) / kSize) * tangent;
        return glm::normalize(forward + u * right + v * up);
    }
    // Angle subtended by one pixel at the image centre (the smallest anywhere else is larger in
    // pixels, so a margin in this angle is at least as many pixels everywhere).
    double pixel_angle() const { return std::atan(2.0 * tangent / kSize); }
};

// The sphere as seen at one frame: its centre and radius.
struct Ball {
    glm::dvec3 centre;
    double radius = 0.0;
};

struct SceneFacts {
    Pinhole camera;
    Ball at[2];  // at kFrames[0], kFrames[1]
};

// The ball's translation at `frame` from its track: linear between the surrounding keyframes,
// held outside them.
glm::dvec3 translation_at(const nlohmann::json& keyframes, double frame) {
    if (frame <= keyframes.front()["frame"].get<double>()) {
        return vec3_of(keyframes.front()["translate"]);
    }
    for (size_t i = 0; i + 1 < keyframes.size(); ++i) {
        const double f0 = keyframes[i]["frame"].get<double>();
        const double f1 = keyframes[i + 1]["frame"].get<double>();
        if (frame <= f1) {
            const double s = (frame - f0) / (f1 - f0);
            return (1.0 - s) * vec3_of(keyframes[i]["translate"]) +
                   s * vec3_of(keyframes[i + 1]["translate"]);
        }
    }
    return vec3_of(keyframes.back()["translate"]);
}

SceneFacts read_scene_facts() {
    const nlohmann::json scene = nlohmann::json::parse(read_file(scene_path()), nullptr, true,
                                                       /*ignore_comments=*/true);
    SceneFacts facts;
    const nlohmann::json& camera = scene["camera"];
    EXPECT_FALSE(camera.contains("fov_axis")) << "the test assumes the default fov_axis x";
    Pinhole& c = facts.camera;
    c.eye = vec3_of(camera["position"]);
    c.forward = glm::normalize(vec3_of(camera["look_at"]) - c.eye);
    c.right = glm::normalize(glm::cross(c.forward, vec3_of(camera["up"])));
    c.up = glm::cross(c.right, c.forward);
    c.tangent = std::tan(camera["fov"].get<double>() * M_PI / 360.0);
    double radius = 0.0;
    for (const nlohmann::json& shape : scene["shapes"]) {
        if (shape["name"] == "ball") {
            // Centred at the origin, no transform: the track's rotation turns the ball in place
            // and its translation is the centre.
            EXPECT_EQ(vec3_of(shape["center"]), glm::dvec3(0.0));
            EXPECT_FALSE(shape.contains("transform"));
            radius = shape["radius"].get<double>();
        }
    }
    EXPECT_GT(radius, 0.0);
    for (const nlohmann::json& track : scene["animation"]["tracks"]) {
        EXPECT_NE(track["target"], "camera") << "the test assumes a still camera";
        if (track["target"] == kBall) {
            for (int i = 0; i < 2; ++i) {
                facts.at[i] = {translation_at(track["keyframes"], kFrames[i]), radius};
            }
        }
    }
    return facts;
}

// Where a pixel lies relative to the ball's disc on screen, with a margin of kMarginPixels.
enum class Side { kInside, kOutside, kBorder };

Side side_of(const Pinhole& camera, const Ball& ball, int x, int y) {
    const glm::dvec3 to_centre = ball.centre - camera.eye;
    const double half_angle = std::asin(ball.radius / glm::length(to_centre));
    const double angle =
        std::acos(std::clamp(glm::dot(camera.ray(x, y), glm::normalize(to_centre)), -1.0, 1.0));
    const double margin = kMarginPixels * camera.pixel_angle();
    if (angle < half_angle - margin) {
        return Side::kInside;
    }
    return angle > half_angle + margin ? Side::kOutside : Side::kBorder;
}

Image render_frame(const std::filesystem::path& dir, const std::string& method, int frame, int spp,
                   const std::vector<std::string>& extra = {}) {
    const std::filesystem::path output = dir / (method + std::to_string(frame) + ".exr");
    std::vector<std::string> args = {
        "render",   scene_path().string(),
        "-o",       output.string(),
        "--method", method,
        "--frames", std::to_string(frame) + ":" + std::to_string(frame),
        "--width",  std::to_string(kSize),
        "--height", std::to_string(kSize),
        "--spp",    std::to_string(spp),
        "--seed",   "7",
        "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    const test::CommandResult result = test::run_radcache(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_image(output);
}

bool same_pixel(const Image& a, const Image& b, int x, int y) {
    for (int c = 0; c < a.channels; ++c) {
        if (a.at(x, y, c) != b.at(x, y, c)) {
            return false;
        }
    }
    return true;
}

// The geometry preview has no light transport: a pixel changes between frames exactly where the
// ball covers it in one frame and not in the other.
TEST(AnimationFrames, NormalsChangeInsideOneFramesDiscOnly) {
    const SceneFacts facts = read_scene_facts();
    const auto dir = test::scratch_dir("animation_frames_normals");
    const Image a = render_frame(dir, "normals", kFrames[0], 4);
    const Image b = render_frame(dir, "normals", kFrames[1], 4);
    ASSERT_EQ(a.channels, b.channels);
    int moved = 0;
    int still = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Side in_a = side_of(facts.camera, facts.at[0], x, y);
            const Side in_b = side_of(facts.camera, facts.at[1], x, y);
            if (in_a == Side::kOutside && in_b == Side::kOutside) {
                EXPECT_TRUE(same_pixel(a, b, x, y)) << "pixel (" << x << ", " << y << ")";
                ++still;
            } else if ((in_a == Side::kInside && in_b == Side::kOutside) ||
                       (in_a == Side::kOutside && in_b == Side::kInside)) {
                EXPECT_FALSE(same_pixel(a, b, x, y)) << "pixel (" << x << ", " << y << ")";
                ++moved;
            }
        }
    }
    std::printf("%d pixels moved, %d still\n", moved, still);
    // Both discs are several pixels across and the test looked at most of the image.
    EXPECT_GT(moved, 2 * 20);
    EXPECT_GT(still, kSize * kSize / 2);
}

// Mean and standard error of the mean of one channel of the beauty over a set of pixels, the
// error from the stddev layer (one sample's standard deviation; the pixel mean's is that over
// sqrt(spp), pixels independent).
struct RegionMean {
    double mean = 0.0;
    double error = 0.0;
};

RegionMean region_mean(const Image& beauty, const Image& stddev, int spp, int channel,
                       const std::vector<std::pair<int, int>>& pixels) {
    double sum = 0.0;
    double variance = 0.0;
    for (const auto& [x, y] : pixels) {
        sum += beauty.at(x, y, channel);
        const double s = stddev.at(x, y, channel);
        variance += s * s / spp;
    }
    const double n = static_cast<double>(pixels.size());
    return {sum / n, std::sqrt(variance) / n};
}

// Path traced: inside the discs the frames differ beyond noise; where the upper half of the box
// shows (rays going up hit surfaces above the ball's top, so no shadow of the ball reaches them)
// the means agree within noise. The bound kSigmas (e_a + e_b) holds whatever the correlation of
// the two frames' noise (same seed).
TEST(AnimationFrames, PathTracedFramesDifferInTheDiscsAndAgreeAboveTheBall) {
    const SceneFacts facts = read_scene_facts();
    for (const Ball& ball : facts.at) {
        ASSERT_LT(ball.centre.y + ball.radius, facts.camera.eye.y);
    }
    const auto dir = test::scratch_dir("animation_frames_pt");
    // 64 samples: the region means' standard errors are ~1.2% above the ball, so a change of a
    // few percent there (a lost bounce: 8%) fails. The ball's real effect there (its indirect
    // light) was measured at 1024 samples: under 0.7 standard errors, 0.2% of the mean.
    const int spp = 64;
    const Image frame_a = render_frame(dir, "pt", kFrames[0], spp, {"--aovs", "beauty,stddev"});
    const Image frame_b = render_frame(dir, "pt", kFrames[1], spp, {"--aovs", "beauty,stddev"});
    const Image beauty[2] = {select_layers(frame_a, {"beauty"}),
                             select_layers(frame_b, {"beauty"})};
    const Image stddev[2] = {select_layers(frame_a, {"stddev"}),
                             select_layers(frame_b, {"stddev"})};
    std::vector<std::pair<int, int>> above, disc[2];
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Side in_a = side_of(facts.camera, facts.at[0], x, y);
            const Side in_b = side_of(facts.camera, facts.at[1], x, y);
            if (in_a == Side::kInside && in_b == Side::kOutside) {
                disc[0].push_back({x, y});
            } else if (in_a == Side::kOutside && in_b == Side::kInside) {
                disc[1].push_back({x, y});
            } else if (in_a == Side::kOutside && in_b == Side::kOutside &&
                       facts.camera.ray(x, y).y > 0.0) {
                above.push_back({x, y});
            }
        }
    }
    ASSERT_GT(above.size(), static_cast<size_t>(kSize * kSize / 4));
    for (int c = 0; c < 3; ++c) {
        const RegionMean a = region_mean(beauty[0], stddev[0], spp, c, above);
        const RegionMean b = region_mean(beauty[1], stddev[1], spp, c, above);
        std::printf("above the ball, channel %d: %.5f vs %.5f, %.2f standard errors apart\n", c,
                    a.mean, b.mean, std::fabs(a.mean - b.mean) / (a.error + b.error));
        EXPECT_LE(std::fabs(a.mean - b.mean), kSigmas * (a.error + b.error))
            << "channel " << c << ": " << a.mean << " +- " << a.error << " vs " << b.mean << " +- "
            << b.error;
    }
    // The ball (blue) replaces the walls and floor behind it in each frame's disc: some channel's
    // mean moves beyond the noise.
    for (const auto& pixels : disc) {
        ASSERT_GT(pixels.size(), 10u);
        double largest = 0.0;
        for (int c = 0; c < 3; ++c) {
            const RegionMean a = region_mean(beauty[0], stddev[0], spp, c, pixels);
            const RegionMean b = region_mean(beauty[1], stddev[1], spp, c, pixels);
            largest = std::max(largest, std::fabs(a.mean - b.mean) / (a.error + b.error));
        }
        std::printf("in a disc: %.1f standard errors apart\n", largest);
        EXPECT_GT(largest, kSigmas) << "frames alike where the ball moved (in standard errors)";
    }
}

}  // namespace
}  // namespace rc
