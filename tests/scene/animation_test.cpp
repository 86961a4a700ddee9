// Animation tracks: transforms exact at keyframes, linear translation and slerp rotation between
// them, held outside; shapes, emitters and the camera follow their tracks.
#include "scene/animation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene_loader.h"
#include "scene/transform.h"
#include "test_support.h"

namespace rc {
namespace {

AnimationTrack two_keyframes() {
    AnimationTrack track;
    Keyframe a;
    a.frame = 0.0;
    a.translate = {1.0f, 2.0f, 3.0f};
    a.rotate = glm::angleAxis(0.0f, glm::vec3(0, 1, 0));
    Keyframe b;
    b.frame = 10.0;
    b.translate = {11.0f, -2.0f, 3.0f};
    b.rotate = glm::angleAxis(glm::radians(120.0f), glm::vec3(0, 1, 0));
    track.keyframes = {a, b};
    return track;
}

void expect_near(glm::vec3 a, glm::vec3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Animation, ExactAtKeyframesAndHeldOutside) {
    const AnimationTrack track = two_keyframes();
    const glm::vec3 x(1.0f, 0.0f, 0.0f);
    // Frame 0: translation only.
    EXPECT_EQ(transform_point(track.at(0.0), glm::vec3(0.0f)), glm::vec3(1.0f, 2.0f, 3.0f));
    expect_near(transform_point(track.at(0.0), x), {2.0f, 2.0f, 3.0f}, 1e-6f);
    // Frame 10: rotation by 120 degrees about y, then translation.
    const float c = std::cos(glm::radians(120.0f));
    const float s = std::sin(glm::radians(120.0f));
    expect_near(transform_point(track.at(10.0), x), glm::vec3(11.0f + c, -2.0f, 3.0f - s), 1e-5f);
    // Before the first and after the last keyframe the ends hold.
    EXPECT_EQ(track.at(-5.0), track.at(0.0));
    EXPECT_EQ(track.at(25.0), track.at(10.0));
}

TEST(Animation, LinearTranslationAndSlerpRotationBetween) {
    const AnimationTrack track = two_keyframes();
    for (double frame : {2.5, 5.0, 7.5}) {
        const float s = static_cast<float>(frame / 10.0);
        const glm::vec3 centre = transform_point(track.at(frame), glm::vec3(0.0f));
        expect_near(centre, glm::vec3(1.0f + 10.0f * s, 2.0f - 4.0f * s, 3.0f), 1e-5f);
        // Slerp turns at a constant rate: the angle is s * 120 degrees about y.
        const float angle = glm::radians(120.0f) * s;
        const glm::vec3 turned = transform_point(track.at(frame), glm::vec3(1.0f, 0.0f, 0.0f));
        expect_near(turned - centre, glm::vec3(std::cos(angle), 0.0f, -std::sin(angle)), 1e-5f);
    }
}

// The moving-sphere scene: the ball's centre follows its track; the camera and walls do not
// move.
TEST(Animation, SceneShapesFollowTheirTracks) {
    Scene scene = load_scene(test::source_dir() / "scenes/moving-sphere/scene.json");
    EXPECT_EQ(scene.animation.frame_start, 0.0);
    EXPECT_EQ(scene.animation.frame_end, 23.0);
    const auto ball_centre = [&] {
        for (const Shape& shape : scene.shapes) {
            if (shape.name == "ball") {
                std::vector<bool> seen(scene.mesh.positions.size(), false);
                for (size_t t = shape.first_triangle;
                     t < shape.first_triangle + shape.triangle_count; ++t) {
                    for (int k = 0; k < 3; ++k) {
                        const unsigned v = scene.mesh.triangles[t][k];
                        seen[v] = true;
                    }
                }
                // The centre of the ball's bounding box (the ball turns about its vertical axis,
                // which keeps the box centred).
                glm::vec3 lower(1e30f), upper(-1e30f);
                for (size_t v = 0; v < seen.size(); ++v) {
                    if (seen[v]) {
                        lower = glm::min(lower, scene.mesh.positions[v]);
                        upper = glm::max(upper, scene.mesh.positions[v]);
                    }
                }
                return 0.5f * (lower + upper);
            }
        }
        ADD_FAILURE() << "no ball";
        return glm::vec3(0.0f);
    };
    const glm::vec3 floor_vertex = scene.mesh.positions[scene.mesh.triangles[0].x];
    expect_near(ball_centre(), {430.0f, 70.0f, 200.0f}, 0.05f);
    scene.set_frame(23.0);
    expect_near(ball_centre(), {130.0f, 70.0f, 330.0f}, 0.05f);
    scene.set_frame(11.5);
    expect_near(ball_centre(), {280.0f, 70.0f, 265.0f}, 0.05f);
    EXPECT_EQ(scene.mesh.positions[scene.mesh.triangles[0].x], floor_vertex);
    EXPECT_EQ(scene.camera.position, glm::vec3(278.0f, 273.0f, -800.0f));
}

TEST(Animation, CameraAndEmitterTracks) {
    const auto dir = test::scratch_dir("animation_tracks");
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 0, -5], "look_at": [0, 0, 0], "fov": 40},
        "shapes": [{"type": "rectangle"}],
        "emitters": [{"type": "point", "name": "bulb", "position": [0, 1, 0], "intensity": 1}],
        "animation": {"frame_start": 0, "frame_end": 4, "tracks": [
            {"target": "camera", "keyframes": [{"frame": 0}, {"frame": 4, "translate": [8, 0, 0]}]},
            {"target": "emitter:bulb", "keyframes": [
                {"frame": 0}, {"frame": 4, "rotate": {"axis": [0, 0, 1], "angle": 90}}]}
        ]}
    })";
    Scene scene = load_scene(dir / "scene.json");
    EXPECT_EQ(scene.camera.position, glm::vec3(0.0f, 0.0f, -5.0f));
    scene.set_frame(2.0);
    expect_near(scene.camera.position, {4.0f, 0.0f, -5.0f}, 1e-5f);
    expect_near(scene.camera.look_at, {4.0f, 0.0f, 0.0f}, 1e-5f);
    const shared::Light& bulb = scene.lights.lights.back();
    ASSERT_EQ(bulb.kind, RC_LIGHT_POINT);
    // Rotated by 45 degrees about z: (0, 1, 0) -> (-sin 45, cos 45, 0).
    EXPECT_NEAR(bulb.position.x, -std::sqrt(0.5f), 1e-5f);
    EXPECT_NEAR(bulb.position.y, std::sqrt(0.5f), 1e-5f);
}

}  // namespace
}  // namespace rc
