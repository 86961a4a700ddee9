// Temporal caching where records can live (docs/temporal-caching.md, "Lifespans"): in a
// walkthrough (only the camera moves) no record expires, and a frame adds first-level records
// only where its view sees surfaces no earlier record covers, by the coverage rule of irradiance
// caching written out here (Ward's weight positive: within a R and in front, not past the
// record's nearest occluder); --temporal-max-frames given still bounds every record. And slow
// motion: the reprojected change of records beside an object moved by 1/s of a step shrinks with
// the motion, so that their lifespans grow with s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "box_walls.h"
#include "image_options.h"
#include "methods/temporal/temporal_cache.h"
#include "posed_frames.h"
#include "scene/scene_loader.h"
#include "temporal_records.h"
#include "test_support.h"

namespace rc {
namespace {

// The shipped walkthrough (scenes/walkthrough) posed at each frame, on the device.
class WalkthroughFrames : public test::PosedFrames {
   public:
    WalkthroughFrames()
        : PosedFrames(load_scene(test::source_dir() / "scenes" / "walkthrough" / "scene.json")) {}
};

glm::vec3 xyz(const shared::float4& v) { return {v.x, v.y, v.z}; }

// The closed box lit by a small area light under its ceiling, with a red cube (0.5 m) on its floor
// at x = -0.04 at frame 0 and x = -0.04 + `step` at frame 1; its scene file.
std::filesystem::path moving_cube_scene(const std::string& name, double step) {
    char animation[512];
    std::snprintf(animation, sizeof animation, R"({"frame_start": 0, "frame_end": 1, "tracks": [
            {"target": "shape:cube", "keyframes": [
                {"frame": 0, "translate": [-0.04, -0.75, 0]},
                {"frame": 1, "translate": [%.6f, -0.75, 0]}]}]})",
                  -0.04 + step);
    return test::temporal_box_scene(name, 16, false,
                                    R"(,
            {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 8},
             "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 0.99, 0]}]},
            {"type": "cube", "name": "cube", "material": "red", "transform": [{"scale": 0.25}]})",
                                    "", animation);
}

// Whether record r gives a positive weight at (p, n): irradiance caching's coverage
// (docs/irradiance-caching.md): p not behind the record's plane (beyond 1e-3 a R), Ward's error
// |p - p_i| / R + sqrt(1 - n . n_i) below a, and p not past the plane through the record's
// nearest occluder o, (p - p_i) . o <= o . o.
bool covers(const TemporalRecord& r, const glm::vec3& p, const glm::vec3& n, float accuracy) {
    const glm::vec3 offset = p - xyz(r.computed.record.position);
    const glm::vec3 ni = xyz(r.computed.record.normal);
    const float radius = r.computed.record.radius;
    if (glm::dot(offset, 0.5f * (n + ni)) < -1e-3f * accuracy * radius) {
        return false;
    }
    const double error = glm::length(offset) / radius +
                         std::sqrt(std::max(0.0, 1.0 - static_cast<double>(glm::dot(n, ni))));
    if (error >= accuracy) {
        return false;
    }
    const glm::vec3 o = xyz(r.computed.payload.occluder);
    return !(glm::dot(offset, o) > glm::dot(o, o));
}

struct Walk {
    std::vector<nlohmann::json> stats;  // per frame: the frame's "temporal" statistics
    std::unique_ptr<TemporalIrradianceCache> cache;
};

// Frames first..last of the walkthrough at 24 x 24 pixels, 1 sample, 128 rays, two cache levels.
Walk walk(WalkthroughFrames& frames, int first, int last, const TemporalOptions& temporal) {
    auto ic = test::image_options<PipelineSettings>(24, 24, 1);
    ic.rays = 128;
    ic.max_depth = frames.scene().render.max_depth;
    ic.records_overlay = false;
    Walk w;
    w.cache = std::make_unique<TemporalIrradianceCache>(ic, temporal, first, last - first + 1);
    FrameHooks hooks;
    hooks.visit_frame = [&](int other, const std::function<void(const FrameScene&)>& use) {
        use(frames.at(other));
    };
    for (int f = first; f <= last; ++f) {
        w.stats.push_back(w.cache->render_frame(frames.at(f), hooks).stats["temporal"]);
    }
    return w;
}

// Frames 20-27 (the camera walking through the doorway, 0.2 m a frame): every record of both
// levels serves to the clip's end, none is recomputed or dropped, and each first-level record
// created after frame 20 lies where no record of an earlier frame covers it. Some are created
// after frame 20 (the view uncovers the next room), fewer than frame 20's.
TEST(TemporalWalkthrough, RecordsLiveTheClipAndNewOnesLieWhereNoneCovers) {
    WalkthroughFrames frames;
    TemporalOptions temporal;
    temporal.enabled = true;
    constexpr int kFirst = 20;
    constexpr int kLast = 27;
    const Walk w = walk(frames, kFirst, kLast, temporal);
    for (int level = 0; level < 2; ++level) {
        ASSERT_FALSE(w.cache->records(level).empty()) << level;
        for (const TemporalRecord& r : w.cache->records(level)) {
            EXPECT_EQ(r.created + r.lifespan, kLast + 1) << "level " << level;
        }
    }
    size_t later = 0;
    for (size_t i = 0; i < w.stats.size(); ++i) {
        EXPECT_EQ(w.stats[i]["recomputed"].get<size_t>(), 0u) << i;
        EXPECT_EQ(w.stats[i]["dropped"].get<size_t>(), 0u) << i;
        later += i > 0 ? w.stats[i]["created"].get<size_t>() : 0u;
    }
    const std::vector<TemporalRecord>& records = w.cache->records(0);
    const float accuracy = PipelineSettings{}.accuracy;
    size_t created_later = 0;
    for (const TemporalRecord& r : records) {
        if (r.created == kFirst) {
            continue;
        }
        ++created_later;
        const glm::vec3 p = xyz(r.computed.record.position);
        const glm::vec3 n = xyz(r.computed.record.normal);
        for (const TemporalRecord& earlier : records) {
            if (earlier.created < r.created) {
                EXPECT_FALSE(covers(earlier, p, n, accuracy))
                    << "a record of frame " << r.created << " where one of frame "
                    << earlier.created << " covers it";
            }
        }
    }
    const size_t first_frame = w.stats[0]["created"].get<size_t>();
    std::printf("records: %zu created at frame %d, %zu at frames %d-%d\n", first_frame, kFirst,
                later, kFirst + 1, kLast);
    EXPECT_EQ(created_later, later);
    EXPECT_GT(later, 0u);
    EXPECT_LT(later, first_frame);
}

// --temporal-max-frames given bounds the records of a walkthrough too: with 3, records created
// at frame 20 expire at frame 23 (replaced or dropped there).
TEST(TemporalWalkthrough, MaxFramesGivenBoundsEveryRecord) {
    WalkthroughFrames frames;
    TemporalOptions temporal;
    temporal.enabled = true;
    temporal.max_frames = 3;
    temporal.max_frames_given = true;
    const Walk w = walk(frames, 20, 25, temporal);
    for (const TemporalRecord& r : w.cache->records(0)) {
        EXPECT_LE(r.lifespan, 3);
    }
    EXPECT_GT(w.stats[3]["recomputed"].get<size_t>() + w.stats[3]["dropped"].get<size_t>(), 0u);
}

// Slow motion: a lit cube on the floor of the closed box moves by 8 cm / s between frames 0 and
// 1 (s = 1, 2, 4, 8). Records of 1024 rays at 24 floor sites around it (path-traced beyond their
// hits) at frame 0 and their reprojection to frame 1: their mean estimated change falls at least
// as s / 2, so that a^t / change, the frames a record serves beyond its first (eqs. 9-10), grows
// at least as s / 2. (Measured: 5.5x at s = 8 with a moved sample covering its own cell carried
// by its motion; 4.8x with the earlier square on its jittered ray, docs/lab/temporal-caching.md.)
TEST(TemporalWalkthrough, SlowerMotionGivesSmallerEstimatedChanges) {
    std::vector<RecordSite> sites;
    for (int i = 0; i < 24; ++i) {
        const float angle = 2.0f * 3.14159265f * (static_cast<float>(i) + 0.5f) / 24.0f;
        const float distance = i % 2 == 0 ? 0.5f : 0.7f;
        RecordSite s;
        s.position = {distance * std::cos(angle), -1.0f, distance * std::sin(angle)};
        s.normal = {0.0f, 1.0f, 0.0f};
        s.origin = s.position + glm::vec3(0.0f, 1e-3f, 0.0f);
        s.r_min = 0.01f;
        s.r_max = 1.0f;
        sites.push_back(s);
    }
    const float accuracy = TemporalOptions{}.accuracy;
    PipelineSettings options = test::image_options<PipelineSettings>(4, 4, 1, 11);
    options.max_depth = 8;
    options.rays = 1024;
    options.bounces = 1;
    options.records_overlay = false;
    std::map<int, double> mean_change;
    for (int s : {1, 2, 4, 8}) {
        const auto path = moving_cube_scene("temporal_slow_" + std::to_string(s), 0.08 / s);
        test::DeviceFrame frame0(test::load_scene_at_frame(path, 0));
        const Scene next = test::load_scene_at_frame(path, 1);
        std::vector<CarriedRecord> carried;
        const auto e0 = records_at_sites(frame0.frame(), sites, options, &next, &carried);
        double change = 0.0;
        size_t unchanged = 0;
        for (size_t i = 0; i < sites.size(); ++i) {
            const float c = temporal_change(e0[i], carried[i].next);
            change += c / sites.size();
            unchanged += c == 0.0f ? 1 : 0;
        }
        mean_change[s] = change;
        std::printf(
            "1/%d of the step: mean change %.5f (%zu of %zu sites none), lifespan "
            "1 + a^t / change %.1f frames\n",
            s, change, unchanged, sites.size(), 1.0 + accuracy / change);
    }
    ASSERT_GT(mean_change[1], accuracy / 4.0);  // the full step shows
    for (int s : {2, 4, 8}) {
        EXPECT_LE(mean_change[s], 2.0 * mean_change[1] / s) << "1/" << s << " of the step";
    }
}

// A clip still for frames 0-4, a cube moving from frame 4 to 6, still again after: every record
// made while still (frames 0-3) expires at frame 5, the first after the motion begins, and is
// replaced or dropped there; those made at frames 6 and 7 (still to the next frame) serve to the
// clip's end (8).
TEST(TemporalWalkthrough, StillRecordsExpireWhenSomethingStartsMoving) {
    const auto path =
        test::temporal_box_scene("temporal_starts_moving", 16, false,
                                 R"(,
            {"type": "cube", "name": "cube", "material": "red", "transform": [{"scale": 0.25}]})",
                                 R"({"type": "point", "position": [0, 0.6, 0], "intensity": 2})",
                                 R"({"frame_start": 0, "frame_end": 7, "tracks": [
            {"target": "shape:cube", "keyframes": [
                {"frame": 4, "translate": [-0.2, -0.75, 0]},
                {"frame": 6, "translate": [0.2, -0.75, 0]}]}]})");
    test::PosedFrames frames(load_scene(path));
    auto at = [&](int frame) { return frames.at(frame); };
    auto ic = test::image_options<PipelineSettings>(16, 16, 1);
    ic.rays = 128;
    ic.records_overlay = false;
    TemporalOptions temporal;
    temporal.enabled = true;
    TemporalIrradianceCache cache(ic, temporal, 0, 8);
    FrameHooks hooks;
    hooks.visit_frame = [&](int other, const std::function<void(const FrameScene&)>& use) {
        use(at(other));
    };
    std::vector<nlohmann::json> stats;
    for (int f = 0; f <= 7; ++f) {
        stats.push_back(cache.render_frame(at(f), hooks).stats["temporal"]);
    }
    size_t still = 0;
    for (int level = 0; level < 2; ++level) {
        for (const TemporalRecord& r : cache.records(level)) {
            if (r.created < 4) {
                ++still;
                EXPECT_EQ(r.created + r.lifespan, 5)
                    << "level " << level << ", frame " << r.created;
            } else if (r.created >= 6) {
                EXPECT_EQ(r.created + r.lifespan, 8)
                    << "level " << level << ", frame " << r.created;
            }
        }
    }
    EXPECT_GT(still, 0u);
    EXPECT_GT(stats[5]["recomputed"].get<size_t>() + stats[5]["dropped"].get<size_t>(), 0u);
    for (int f = 1; f <= 4; ++f) {
        EXPECT_EQ(stats[static_cast<size_t>(f)]["recomputed"].get<size_t>(), 0u) << f;
        EXPECT_EQ(stats[static_cast<size_t>(f)]["dropped"].get<size_t>(), 0u) << f;
    }
}

}  // namespace
}  // namespace rc
