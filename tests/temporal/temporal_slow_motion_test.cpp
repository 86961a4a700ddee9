// Slow motion lengthens lifespans (docs/temporal-caching.md, "Lifespans"): a ball rolling over
// the lit floor of the closed box, the same motion k times slower (k = 1, 2, 4, 8). A record's
// lifespan follows its estimated change to the next frame (the report's eqs. 9-12), and that
// estimate shrinks with the motion, with no floor from the jitter of the record's rays
// (rc_tc_carried_cell): the records' mean lifespan grows at least as k / 2.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "box_walls.h"
#include "image_options.h"
#include "methods/temporal/temporal_cache.h"
#include "posed_frames.h"
#include "scene/scene_loader.h"

namespace rc {
namespace {

// The oracle's speeds: the clip k times slower moves the ball by 1/k of the step a frame.
constexpr int kSlowdowns[] = {1, 2, 4, 8};
// The ball's step a frame at the clip's own speed (the box is 2 m wide).
constexpr double kStep = 0.08;
// Long enough that no lifespan measured here reaches it (delta t_max, eq. 12, given).
constexpr int kMaxFrames = 100;

// The closed box lit by a small area light under its ceiling, with a ball (radius 0.25 m) on its
// floor at x = -0.04 at frame 0 and x = -0.04 + step at frame 1 (keyframes interpolate linearly:
// the clip k times slower is the step / k); its scene file.
std::filesystem::path rolling_ball_scene(int slowdown) {
    char animation[512];
    std::snprintf(animation, sizeof animation, R"({"frame_start": 0, "frame_end": 1, "tracks": [
            {"target": "shape:ball", "keyframes": [
                {"frame": 0, "translate": [-0.04, -0.75, 0]},
                {"frame": 1, "translate": [%.8f, -0.75, 0]}]}]})",
                  -0.04 + kStep / slowdown);
    return test::temporal_box_scene("temporal_slow_motion_" + std::to_string(slowdown), 16, false,
                                    R"(,
            {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 8},
             "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 0.99, 0]}]},
            {"type": "sphere", "name": "ball", "center": [0, 0, 0], "radius": 0.25,
             "material": "red"})",
                                    "", animation);
}

// The first-level records temporal caching places at frame 0 of a long clip (16 x 16 pixels,
// 1 sample, 256 rays, one cache level path-traced beyond its hits), with their lifespans; the
// frame's statistics count those on the ball.
std::vector<TemporalRecord> records_at_frame_0(int slowdown) {
    test::PosedFrames frames(load_scene(rolling_ball_scene(slowdown)));
    auto ic = test::image_options<PipelineSettings>(16, 16, 1, 5);
    ic.rays = 256;
    ic.bounces = 1;
    ic.max_depth = 8;
    ic.records_overlay = false;
    TemporalOptions temporal;
    temporal.enabled = true;
    temporal.gradients = TemporalGradients::kNone;  // one pass: frame 0 is placed alone
    temporal.max_frames = kMaxFrames;
    temporal.max_frames_given = true;
    TemporalIrradianceCache cache(ic, temporal, 0, 4 * kMaxFrames);
    FrameHooks hooks;
    hooks.visit_frame = [&](int other, const std::function<void(const FrameScene&)>& use) {
        use(frames.at(other));
    };
    const nlohmann::json stats = cache.render_frame(frames.at(0), hooks).stats["temporal"];
    size_t on_moving = 0;
    for (const TemporalRecord& r : cache.records(0)) {
        on_moving += r.site_moves ? 1 : 0;
    }
    EXPECT_EQ(stats["on_moving_surfaces"].get<size_t>(), on_moving);
    return cache.records(0);
}

// Frame 0 is the same pose at every speed, so the same records are placed (same sites, same
// streams); only their estimate of the next frame differs. Over the records that see the ball
// move at the clip's own speed (estimated change above 0; records on the ball itself serve one
// frame whatever the speed, the report's rule, and are left out), the mean lifespan at k times
// slower is at least k / 2 times the mean at the clip's speed.
TEST(TemporalSlowMotion, SlowerClipsGiveProportionallyLongerLifespans) {
    std::map<int, std::vector<TemporalRecord>> records;
    for (int k : kSlowdowns) {
        records[k] = records_at_frame_0(k);
    }
    const std::vector<TemporalRecord>& normal = records[1];
    std::vector<size_t> seeing;
    for (size_t i = 0; i < normal.size(); ++i) {
        const TemporalRecord& r = normal[i];
        if (!r.site_moves && temporal_change(r.computed.payload, r.next) > 0.0f) {
            seeing.push_back(i);
        }
    }
    ASSERT_GE(seeing.size(), 10u) << "records seeing the ball move, of " << normal.size();
    std::map<int, double> mean;
    for (int k : kSlowdowns) {
        ASSERT_EQ(records[k].size(), normal.size()) << k << "x slower";
        double sum = 0.0;
        for (size_t i : seeing) {
            const TemporalRecord& r = records[k][i];
            ASSERT_EQ(r.computed.record.position.x, normal[i].computed.record.position.x);
            ASSERT_EQ(r.computed.record.position.z, normal[i].computed.record.position.z);
            sum += r.lifespan;
        }
        mean[k] = sum / static_cast<double>(seeing.size());
        std::printf("%dx slower: mean lifespan %.2f frames over %zu records (of %zu)\n", k, mean[k],
                    seeing.size(), normal.size());
    }
    // The motion at the clip's speed shortens lives well below delta t_max, so that 8x longer
    // ones are not cut by it.
    ASSERT_LT(8.0 * mean[1], kMaxFrames);
    for (int k : kSlowdowns) {
        EXPECT_GE(mean[k], 0.5 * k * mean[1]) << k << "x slower";
    }
}

}  // namespace
}  // namespace rc
