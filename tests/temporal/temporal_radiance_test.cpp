// Temporal radiance caching (`--method rc --temporal`; host/methods/temporal/
// temporal_radiance_cache.h) against independent oracles: a radiance record's reprojected
// estimate when the light's power doubles is twice its coefficients exactly (change 1, the
// report's tau = 2), and the record itself when nothing changes; after an object moves, the
// reprojected estimate lies nearer a record computed fresh at the next frame than the record
// does; a static scene over frames is frame 0's single-frame `rc` image every frame with nothing
// recomputed; an animation is the same bit for bit in other launch chunks and work-groups, and
// its records are reused, replaced and dropped as the stats say; bad combinations refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "box_walls.h"
#include "frame_renders.h"
#include "image/image_io.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/radiance_cache/tc_radiance_reprojection.h"
#include "methods/radiance_cache/temporal_radiance_record.h"
#include "methods/radiance_source.h"
#include "methods/temporal/tc_motion.h"
#include "methods/temporal/temporal_record.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

// test::temporal_box_scene at 24 x 24 pixels, the back wall glossy so that the BRDF tables have an
// order (every wall faces an emitter inside), in scratch folder temporal_radiance_`name`.
std::filesystem::path glossy_box(const std::string& name, const std::string& shapes,
                                 const std::string& emitters, const std::string& animation) {
    return test::temporal_box_scene("temporal_radiance_" + name, 24, true, shapes, emitters,
                                    animation);
}

constexpr const char* kStill = test::kStillAnimation;

// Radiance-record sites on the floor (y = -1, normal up) at the given (x, z).
std::vector<shared::RcQuery> floor_sites(const std::vector<std::pair<float, float>>& xz) {
    std::vector<shared::RcQuery> sites;
    for (const auto& [x, z] : xz) {
        shared::RcQuery q{};
        q.position = {x, -1.0f, z, 0.0f};
        q.origin = {x, -1.0f + 1e-3f, z, 0.0f};
        q.normal = q.geometric_normal = {0.0f, 1.0f, 0.0f, 0.0f};
        q.tangent = {1.0f, 0.0f, 0.0f, 0.0f};
        q.outgoing = {0.0f, 0.0f, 1.0f, 0.0f};
        q.footprint = 0.01f;
        q.material = 0;
        q.order = 1;
        q.primitive = -1;
        sites.push_back(q);
    }
    return sites;
}

RadianceCacheOptions record_options(int rays, uint64_t seed, int max_depth) {
    RadianceCacheOptions options;
    options.rays = rays;
    options.seed = seed;
    options.max_depth = max_depth;
    return options;
}

// Places records at `sites` in `cache` (site i's random stream i): their payloads, in order.
std::vector<std::vector<float>> add_records(RadianceCache& cache,
                                            const std::vector<shared::RcQuery>& sites) {
    std::vector<unsigned> streams;
    for (size_t i = 0; i < sites.size(); ++i) {
        streams.push_back(static_cast<unsigned>(i));
    }
    cache.add_records(sites, streams, PathContinuation());
    std::vector<std::vector<float>> payloads;
    const size_t floats = static_cast<size_t>(9 * cache.order() * cache.order());
    for (size_t i = 0; i < sites.size(); ++i) {
        const auto* data = reinterpret_cast<const float*>(cache.store().payload_data(i));
        payloads.emplace_back(data, data + floats);
    }
    return payloads;
}

// Radiance records at `sites` of `scene` posed at frame 0 with `rays` rays (path-traced beyond
// their hits to `max_depth`): their payloads, in order, and their reprojected estimates at the
// next frame (`next`: the scene posed there) into *carried; the records' order into *order.
std::vector<std::vector<float>> records_at(const std::filesystem::path& scene, const Scene& next,
                                           const std::vector<shared::RcQuery>& sites, int rays,
                                           uint64_t seed, int max_depth,
                                           std::vector<CarriedRadianceRecord>* carried,
                                           int* order) {
    test::DeviceFrame device(test::load_scene_at_frame(scene, 0));
    const FrameScene frame = device.frame();
    RadianceCache cache(frame, record_options(rays, seed, max_depth));
    *order = cache.order();
    const TcMotion motion(frame.context, frame.scene, next, 0, 4);
    TcRadianceReprojection reprojection(frame, motion, cache.order());
    cache.set_observer(&reprojection);
    std::vector<std::vector<float>> payloads = add_records(cache, sites);
    *carried = reprojection.take();
    return payloads;
}

// A point light whose intensity doubles from one frame to the next, everything else still: every
// hemisphere hit sees it (a closed box, the light inside), so every carried sample doubles and so
// does every coefficient and gradient (exactly: doubling is exact in floating point), the change
// is 1 (tau = 2) and the lifespan at the default accuracy one frame. The same scene as its own
// next frame gives the record's payload bit for bit, change 0 and the longest lifespan.
TEST(TemporalRadianceCaching, LightWhosePowerDoublesDoublesEveryCoefficient) {
    const auto once = glossy_box("power_1", "", R"({"type": "point", "position": [0.2, 0.4, 0.1],
                                                   "intensity": 3})",
                                 kStill);
    const auto twice = glossy_box("power_2", "", R"({"type": "point", "position": [0.2, 0.4, 0.1],
                                                    "intensity": 6})",
                                  kStill);
    const std::vector<shared::RcQuery> sites =
        floor_sites({{0.0f, 0.0f}, {-0.5f, 0.3f}, {0.7f, -0.4f}});
    std::vector<CarriedRadianceRecord> carried;
    int order = 0;
    const auto now = records_at(once, load_scene(twice), sites, 1024, 5, 64, &carried, &order);
    ASSERT_GT(order, 2);
    ASSERT_EQ(carried.size(), sites.size());
    for (size_t i = 0; i < sites.size(); ++i) {
        EXPECT_GT(now[i][0], 0.0f);
        for (size_t k = 0; k < now[i].size(); ++k) {
            ASSERT_EQ(carried[i].next[k], 2.0f * now[i][k]) << i << " " << k;
        }
        const float change = radiance_temporal_change(now[i], carried[i].next, order);
        EXPECT_FLOAT_EQ(change, 1.0f);
        EXPECT_EQ(temporal_lifespan(change, TemporalOptions{}, carried[i].site_moves), 1);
    }
    const auto same = records_at(once, load_scene(once), sites, 1024, 5, 64, &carried, &order);
    for (size_t i = 0; i < sites.size(); ++i) {
        EXPECT_EQ(carried[i].next, same[i]) << i;
        EXPECT_EQ(radiance_temporal_change(same[i], carried[i].next, order), 0.0f);
    }
}

// Relative L2 distance of two payloads' coefficient vectors of order `order` (all channels),
// over their first `bands` bands.
double coefficient_distance(const std::vector<float>& a, const std::vector<float>& b, int order,
                            int bands) {
    const size_t count = static_cast<size_t>(order * order);
    double difference = 0.0;
    double norm = 0.0;
    for (size_t c = 0; c < 3; ++c) {
        for (size_t k = c * count; k < c * count + static_cast<size_t>(bands * bands); ++k) {
            difference += (static_cast<double>(a[k]) - b[k]) * (static_cast<double>(a[k]) - b[k]);
            norm += static_cast<double>(b[k]) * b[k];
        }
    }
    return std::sqrt(difference / norm);
}

// A lit red cube on the floor moves by 10 cm between frames 0 and 1. Radiance records of 4096
// rays on the floor beside it (direct light beyond their hits, max_depth 2): the estimate of
// their coefficients at frame 1 reprojected from frame 0's samples lies nearer records computed
// fresh at frame 1 with the same random streams than the frame-0 records do (RMS over the sites
// of the relative L2 distance of the coefficient vectors): under 0.55x as far over the first
// three bands (measured 0.47x: 0.042 against 0.091), under 0.7x over all ten (measured 0.60x:
// 0.063 against 0.105). The high bands keep more of the change: the depth test and hole filling
// place a moved edge to about a cell, which the low bands average out. (Two fresh records with
// different seeds differ by 0.45 over three bands: the same streams are what make the comparison
// sharp.)
TEST(TemporalRadianceCaching, ReprojectionPredictsTheCoefficientsAfterAnObjectMoves) {
    const std::string cube = R"(,
        {"type": "cube", "name": "cube", "material": "red",
         "transform": [{"scale": 0.15}, {"translate": [0.1, -0.85, 0.2]}]})";
    const std::string light = R"({"type": "point", "position": [0.0, 0.8, -0.2], "intensity": 4})";
    const auto moving = glossy_box("moving", cube, light, R"({"frame_start": 0, "frame_end": 1,
        "tracks": [{"target": "shape:cube", "keyframes": [
            {"frame": 0, "translate": [0, 0, 0]}, {"frame": 1, "translate": [0.1, 0, 0]}]}]})");
    const Scene next = test::load_scene_at_frame(moving, 1);
    const std::vector<shared::RcQuery> sites =
        floor_sites({{-0.2f, 0.2f}, {0.1f, -0.1f}, {0.5f, 0.25f}, {0.3f, 0.5f}, {0.1f, 0.5f}});
    std::vector<CarriedRadianceRecord> carried;
    int order = 0;
    const auto now = records_at(moving, next, sites, 4096, 9, 2, &carried, &order);
    // Records computed fresh at frame 1 (seed 9: the same random streams).
    test::DeviceFrame at_frame_1(test::load_scene_at_frame(moving, 1));
    RadianceCache fresh_cache(at_frame_1.frame(), record_options(4096, 9, 2));
    const auto fresh = add_records(fresh_cache, sites);
    const auto distance = [&](const std::vector<std::vector<float>>& estimate, int bands) {
        double sum = 0.0;
        for (size_t i = 0; i < sites.size(); ++i) {
            sum += std::pow(coefficient_distance(estimate[i], fresh[i], order, bands), 2.0);
        }
        return std::sqrt(sum / static_cast<double>(sites.size()));
    };
    std::vector<std::vector<float>> predicted;
    for (const CarriedRadianceRecord& c : carried) {
        predicted.push_back(c.next);
    }
    for (const auto& [bands, bound] : {std::pair<int, double>{3, 0.55}, {order, 0.7}}) {
        const double change = distance(now, bands);
        EXPECT_GT(change, 0.01) << bands;  // the move changes the records measurably
        EXPECT_LT(distance(predicted, bands), bound * change) << bands << " bands";
    }
}

using test::expect_static_glossy_records;
using test::frame_file;
using test::render_frames;
using test::same_pixels;

const std::vector<std::string> kSmall = {"--method", "rc", "--width",   "32",  "--height",  "32",
                                         "--spp",    "2",  "--ic-rays", "256", "--rc-rays", "256"};

// The glossy box (no animation) over frames 0-3 with --temporal: every frame is, every layer bit
// for bit, the single-frame `rc` render; frame 0 creates every radiance record and the later
// frames reuse them all, computing, replacing and dropping none.
TEST(TemporalRadianceCaching, StaticSceneRendersFrameZerosImageEveryFrame) {
    const auto dir = test::scratch_dir("temporal_radiance_static");
    const auto scene = test::source_dir() / "scenes" / "glossy-box" / "scene.json";
    std::vector<std::string> single = {"render", scene.string()};
    single.insert(single.end(), kSmall.begin(), kSmall.end());
    single.insert(single.end(), {"-o", (dir / "single.exr").string(), "--quiet"});
    ASSERT_EQ(test::run_radcache(single).exit_code, 0);
    std::vector<std::string> temporal = kSmall;
    temporal.insert(temporal.end(), {"--temporal", "--frames", "0:3"});
    const nlohmann::json stats = render_frames(scene, dir, "t", temporal);
    const Image expected = read_image(dir / "single.exr");
    expect_static_glossy_records(stats, 3);
    for (int f = 0; f <= 3; ++f) {
        EXPECT_TRUE(same_pixels(read_image(frame_file(dir, "t", f)), expected)) << "frame " << f;
    }
}

// A cube moving across the glossy box's floor over frames 0-5: the whole
// sequence is the same bit for bit in other launch chunks and work-groups; records are reused
// after frame 0, and the stats' counts add up (serving = reused + recomputed + created).
TEST(TemporalRadianceCaching, AnimationIsDeterministicAndReusesRecords) {
    const auto scene =
        glossy_box("animated", R"(,
        {"type": "cube", "name": "cube", "material": "red",
         "transform": [{"scale": 0.15}, {"translate": [0.1, -0.85, 0.2]}]})",
                   R"({"type": "point", "position": [0.0, 0.8, -0.2], "intensity": 4})",
                   R"({"frame_start": 0, "frame_end": 5, "tracks": [
            {"target": "shape:cube", "keyframes": [
                {"frame": 0, "translate": [0, 0, 0]}, {"frame": 5, "translate": [0.4, 0, 0]}]}]})");
    const auto dir = test::scratch_dir("temporal_radiance_animated_frames");
    std::vector<std::string> args = kSmall;
    args.insert(args.end(), {"--temporal", "--frames", "0:5"});
    const nlohmann::json stats = render_frames(scene, dir, "a", args);
    args.insert(args.end(), {"--max-chunk", "333", "--local-size", "8"});
    render_frames(scene, dir, "b", args);
    size_t reused = 0;
    for (int f = 0; f <= 5; ++f) {
        EXPECT_TRUE(
            same_pixels(read_image(frame_file(dir, "a", f)), read_image(frame_file(dir, "b", f))))
            << "frame " << f;
        const nlohmann::json& r = stats["frames"][f]["temporal"]["radiance"];
        EXPECT_EQ(
            r["records"].get<size_t>(),
            r["reused"].get<size_t>() + r["recomputed"].get<size_t>() + r["created"].get<size_t>())
            << f;
        reused += f > 0 ? r["reused"].get<size_t>() : 0u;
    }
    EXPECT_GT(stats["frames"][0]["temporal"]["radiance"]["records"].get<size_t>(), 0u);
    EXPECT_GT(reused, 0u);
}

// rc's cache files with --temporal: one line naming them, exit status 2, no image.
TEST(TemporalRadianceCaching, CacheFilesAreRefusedWithTemporal) {
    const auto dir = test::scratch_dir("temporal_radiance_refused");
    const auto scene = test::source_dir() / "scenes" / "glossy-box" / "scene.json";
    for (const std::string option : {"--rc-cache-out", "--cache-out"}) {
        const test::CommandResult result = test::run_radcache(
            {"render", scene.string(), "--method", "rc", "--temporal", "--frames", "0:1", option,
             (dir / "cache.bin").string(), "-o", (dir / "x####.exr").string()});
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find("--temporal"), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "x0000.exr"));
    }
}

}  // namespace
}  // namespace rc
