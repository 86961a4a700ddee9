// Temporal caching (`--method ic --temporal`, host/methods/temporal/) against independent
// oracles: a static scene over frames is frame 0's single-frame image every frame, nothing
// recomputed; the reprojected estimate of a record's next frame against a record computed fresh
// at that frame (an object moved by a known offset; a light whose power doubles: tau = 2); the
// lifespan of a record whose hemisphere sees no motion is the longest, and one that sees a moving
// light changes by no more than the temporal accuracy over its lifespan (fresh records at its
// last frame); accuracy over the moving sphere's frames against their references; determinism of
// the whole sequence; bad options refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "box_walls.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/temporal/tc_reprojection.h"
#include "methods/temporal/temporal_record.h"
#include "scene/scene_loader.h"
#include "temporal_records.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

// test::temporal_box_scene at 16 x 16 pixels, every wall diffuse, in scratch folder
// temporal_`name`.
std::filesystem::path box_scene(const std::string& name, const std::string& shapes,
                                const std::string& emitters, const std::string& animation) {
    return test::temporal_box_scene("temporal_" + name, 16, false, shapes, emitters, animation);
}

constexpr const char* kNoEmitters = "";
constexpr const char* kStill = test::kStillAnimation;

// Sites on the floor (y = -1, normal up) at the given (x, z).
std::vector<RecordSite> floor_sites(const std::vector<std::pair<float, float>>& xz) {
    std::vector<RecordSite> sites;
    for (const auto& [x, z] : xz) {
        RecordSite s;
        s.position = {x, -1.0f, z};
        s.normal = {0.0f, 1.0f, 0.0f};
        s.origin = {x, -1.0f + 1e-3f, z};
        s.r_min = 0.01f;
        s.r_max = 1.0f;
        sites.push_back(s);
    }
    return sites;
}

PipelineSettings record_options(int rays, uint64_t seed, int max_depth) {
    PipelineSettings o;
    o.max_depth = max_depth;
    o.width = 4;
    o.height = 4;
    o.spp = 1;
    o.rays = rays;
    o.bounces = 1;
    o.seed = seed;
    o.records_overlay = false;
    return o;
}

// Records computed at `sites` of `frame` (their payloads, in order), and with `next` the scene at
// the next frame, their reprojected estimates into *carried.
std::vector<shared::IrradiancePayload> records_at(const FrameScene& frame,
                                                  const std::vector<RecordSite>& sites, int rays,
                                                  uint64_t seed, int max_depth,
                                                  const Scene* next = nullptr,
                                                  std::vector<CarriedRecord>* carried = nullptr) {
    return records_at_sites(frame, sites, record_options(rays, seed, max_depth), next, carried);
}

double luminance(const shared::float4& e) { return 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z; }

// A point light whose intensity doubles from one frame to the next, everything else still: every
// hemisphere hit sees it (a closed box, the light inside), so every carried sample doubles and
// tau = E_1 / E_0 is exactly 2 (the doubling is exact in floating point); the lifespan at a^t =
// 0.05 is one frame. And the same scene as its own next frame gives E_1 = E_0 bit for bit.
TEST(TemporalCaching, LightWhosePowerDoublesGivesTauTwo) {
    const auto once = box_scene("power_1", "", R"({"type": "point", "position": [0.2, 0.4, 0.1],
                                                  "intensity": 3})",
                                kStill);
    const auto twice = box_scene("power_2", "", R"({"type": "point", "position": [0.2, 0.4, 0.1],
                                                   "intensity": 6})",
                                 kStill);
    test::DeviceFrame now(test::load_scene_at_frame(once, 0));
    const Scene next = load_scene(twice);
    const std::vector<RecordSite> sites = floor_sites({{0.0f, 0.0f}, {-0.6f, 0.5f}, {0.7f, -0.4f}});
    std::vector<CarriedRecord> carried;
    const auto e0 = records_at(now.frame(), sites, 1024, 5, 64, &next, &carried);
    ASSERT_EQ(carried.size(), sites.size());
    for (size_t i = 0; i < sites.size(); ++i) {
        EXPECT_GT(e0[i].irradiance.x, 0.0f);
        EXPECT_EQ(carried[i].next.irradiance.x, 2.0f * e0[i].irradiance.x) << i;
        EXPECT_EQ(carried[i].next.irradiance.y, 2.0f * e0[i].irradiance.y) << i;
        EXPECT_EQ(carried[i].next.irradiance.z, 2.0f * e0[i].irradiance.z) << i;
        EXPECT_EQ(carried[i].next.translation_r.x, 2.0f * e0[i].translation_r.x) << i;
        EXPECT_FLOAT_EQ(temporal_change(e0[i], carried[i].next), 1.0f);
        EXPECT_EQ(temporal_lifespan(temporal_change(e0[i], carried[i].next), TemporalOptions{},
                                    carried[i].site_moves),
                  1);
    }
    const Scene same = load_scene(once);
    const auto again = records_at(now.frame(), sites, 1024, 5, 64, &same, &carried);
    for (size_t i = 0; i < sites.size(); ++i) {
        EXPECT_EQ(std::memcmp(&carried[i].next, &again[i], sizeof again[i]), 0) << i;
        EXPECT_EQ(
            temporal_lifespan(temporal_change(again[i], carried[i].next), TemporalOptions{}, false),
            TemporalOptions{}.max_frames);
    }
}

// A lit red cube on the floor moves by 8 cm between frames 0 and 1. Records of 4096 rays on the
// floor around it, with the light beyond their rays' hits limited to direct light (max_depth 2):
// the estimate of their irradiance at frame 1 reprojected from frame 0's samples against records
// computed fresh at frame 1 with the same random streams. Its RMS relative error over the sites
// is within the Monte Carlo error of a record at the method's default 1024 rays (the RMS relative
// spread of such records at frame 1 under four seeds) and under half the RMS relative change
// since frame 0, which the cube's move makes larger than that Monte Carlo error.
TEST(TemporalCaching, ReprojectionPredictsTheIrradianceAfterAnObjectMoves) {
    const auto path = box_scene("moved_cube",
                                R"(,
            {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 8},
             "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 0.99, 0]}]},
            {"type": "cube", "name": "cube", "material": "red", "transform": [{"scale": 0.25}]})",
                                kNoEmitters, R"({"frame_start": 0, "frame_end": 1, "tracks": [
            {"target": "shape:cube", "keyframes": [
                {"frame": 0, "translate": [-0.04, -0.75, 0]},
                {"frame": 1, "translate": [0.04, -0.75, 0]}]}]})");
    test::DeviceFrame frame0(test::load_scene_at_frame(path, 0));
    test::DeviceFrame frame1(test::load_scene_at_frame(path, 1));
    Scene next = test::load_scene_at_frame(path, 1);
    const std::vector<RecordSite> sites = floor_sites({{-0.7f, 0.0f},
                                                       {0.75f, 0.1f},
                                                       {0.0f, 0.55f},
                                                       {0.1f, -0.55f},
                                                       {-0.55f, 0.45f},
                                                       {0.6f, -0.5f}});
    constexpr int kRays = 4096;
    std::vector<CarriedRecord> carried;
    const auto e0 = records_at(frame0.frame(), sites, kRays, 11, 2, &next, &carried);
    const auto e1 = records_at(frame1.frame(), sites, kRays, 11, 2);
    // The Monte Carlo error of a record at the method's default 1024 rays.
    std::vector<std::vector<shared::IrradiancePayload>> fresh;
    for (uint64_t seed : {21, 22, 23, 24}) {
        fresh.push_back(records_at(frame1.frame(), sites, 1024, seed, 2));
    }
    double predicted = 0.0;
    double changed = 0.0;
    double spread = 0.0;
    for (size_t i = 0; i < sites.size(); ++i) {
        const double fresh1 = luminance(e1[i].irradiance);
        const double estimate = luminance(carried[i].next.irradiance);
        const double before = luminance(e0[i].irradiance);
        double mean = 0.0;
        for (const auto& f : fresh) {
            mean += luminance(f[i].irradiance) / fresh.size();
        }
        for (const auto& f : fresh) {
            spread += std::pow(luminance(f[i].irradiance) / mean - 1.0, 2.0) / (fresh.size() - 1);
        }
        std::printf("site %zu: E0 %.4f, estimate %.4f, fresh E1 %.4f\n", i, before, estimate,
                    fresh1);
        predicted += std::pow(estimate / fresh1 - 1.0, 2.0);
        changed += std::pow(before / fresh1 - 1.0, 2.0);
        EXPECT_FALSE(carried[i].site_moves);
    }
    predicted = std::sqrt(predicted / sites.size());
    changed = std::sqrt(changed / sites.size());
    spread = std::sqrt(spread / sites.size());
    std::printf("RMS relative: estimate's error %.4f, change %.4f, Monte Carlo spread %.4f\n",
                predicted, changed, spread);
    EXPECT_GT(changed, spread);  // the move shows above the noise
    EXPECT_LT(predicted, spread);
    EXPECT_LT(predicted, changed / 2.0);
}

// Two closed boxes side by side: box A (x in [-1, 1]) holds a cube moving across it, box B
// (x in [3, 5]) is still, with its own point light. Records on B's floor see no motion: their
// estimate is their value bit for bit and they live the longest lifespan; records on A's floor
// beside the cube live shorter.
TEST(TemporalCaching, StillHemispheresLiveTheLongestLifespan) {
    const auto path = box_scene("two_boxes",
                                R"(,
            {"type": "cube", "name": "cube", "material": "red", "transform": [{"scale": 0.25}]},
            {"type": "cube", "name": "room_b", "material": "white", "flip_normals": true,
             "transform": [{"translate": [4, 0, 0]}]})",
                                R"({"type": "point", "position": [0, 0.6, 0], "intensity": 2},
            {"type": "point", "position": [4, 0.6, 0], "intensity": 2})",
                                R"({"frame_start": 0, "frame_end": 1, "tracks": [
            {"target": "shape:cube", "keyframes": [
                {"frame": 0, "translate": [-0.2, -0.75, 0]},
                {"frame": 1, "translate": [0.2, -0.75, 0]}]}]})");
    test::DeviceFrame frame0(test::load_scene_at_frame(path, 0));
    Scene next = test::load_scene_at_frame(path, 1);
    const std::vector<RecordSite> still = floor_sites({{3.5f, 0.2f}, {4.6f, -0.5f}});
    const std::vector<RecordSite> beside = floor_sites({{0.6f, 0.0f}, {-0.6f, 0.3f}});
    std::vector<RecordSite> sites = still;
    sites.insert(sites.end(), beside.begin(), beside.end());
    std::vector<CarriedRecord> carried;
    const auto e0 = records_at(frame0.frame(), sites, 1024, 3, 64, &next, &carried);
    TemporalOptions options;
    options.max_frames = 20;
    for (size_t i = 0; i < sites.size(); ++i) {
        const int lifespan =
            temporal_lifespan(temporal_change(e0[i], carried[i].next), options, false);
        if (i < still.size()) {
            EXPECT_EQ(std::memcmp(&carried[i].next, &e0[i], sizeof e0[i]), 0) << i;
            EXPECT_EQ(lifespan, options.max_frames) << i;
        } else {
            EXPECT_LT(lifespan, options.max_frames) << i;
        }
    }
}

// A point light moves across the box at constant speed over 20 frames. Records on the floor at
// frame 0 (direct light beyond their rays' hits, so that records at other frames with the same
// streams differ by the light's move alone) get lifespans shorter than the longest; computed
// fresh at the last frame each one serves, their irradiance has changed from frame 0 by no more
// than the temporal accuracy a^t = 0.05 (with 20% slack for the change not being linear).
TEST(TemporalCaching, RecordsSeeingAMovingLightExpireBeforeTheirErrorBound) {
    const auto path = box_scene("moving_light", "", R"({"type": "point", "name": "bulb",
                                                       "position": [0, 0, 0], "intensity": 2})",
                                R"({"frame_start": 0, "frame_end": 20, "tracks": [
            {"target": "emitter:bulb", "keyframes": [
                {"frame": 0, "translate": [-0.6, 0.5, 0]},
                {"frame": 20, "translate": [0.6, 0.5, 0]}]}]})");
    test::DeviceFrame frame0(test::load_scene_at_frame(path, 0));
    Scene next = test::load_scene_at_frame(path, 1);
    const std::vector<RecordSite> sites =
        floor_sites({{-0.5f, 0.0f}, {0.0f, 0.5f}, {0.5f, -0.3f}, {0.8f, 0.7f}, {-0.8f, -0.6f}});
    std::vector<CarriedRecord> carried;
    const auto e0 = records_at(frame0.frame(), sites, 4096, 9, 2, &next, &carried);
    TemporalOptions options;
    options.accuracy = 0.05f;  // the report's
    int checked = 0;
    for (size_t i = 0; i < sites.size(); ++i) {
        const int lifespan =
            temporal_lifespan(temporal_change(e0[i], carried[i].next), options, false);
        ASSERT_LT(lifespan, options.max_frames) << "site " << i << " sees the light move";
        test::DeviceFrame last(test::load_scene_at_frame(path, lifespan - 1));
        const auto e_last = records_at(last.frame(), {sites[i]}, 4096, 9, 2);
        const double change =
            std::fabs(luminance(e_last[0].irradiance) / luminance(e0[i].irradiance) - 1.0);
        std::printf("site %zu: lifespan %d, change over it %.4f\n", i, lifespan, change);
        EXPECT_LE(change, 1.2 * options.accuracy) << "site " << i;
        ++checked;
    }
    EXPECT_EQ(checked, 5);
}

// f(t) = 1 + b t + c t^2 / 2, a record's irradiance over time relative to its value at t_0 = 0.
double quadratic(double b, double c, double t) { return 1.0 + b * t + 0.5 * c * t * t; }

// The oracle of a departure lifespan, by brute force over the frames: the largest departure of
// f(k) from the line from f(0) to f(l), 0 < k < l, relative to f(0) (the error of a record
// serving frames 0 .. l - 1 with interpolated gradients towards an exact replacement at l).
double chord_departure(double b, double c, int l) {
    double worst = 0.0;
    for (int k = 1; k < l; ++k) {
        const double line = 1.0 + (quadratic(b, c, l) - 1.0) * k / l;
        worst = std::max(worst, std::fabs(quadratic(b, c, k) - line));
    }
    return worst;
}

// The longest lifespan (at most delta t_max) whose chord departs by at most a^t, by brute force.
int oracle_departure_lifespan(double b, double c, const TemporalOptions& options) {
    int best = 1;
    for (int l = 2; l <= options.max_frames; ++l) {
        if (chord_departure(b, c, l) <= options.accuracy) {
            best = l;
        }
    }
    return best;
}

shared::IrradiancePayload payload_of(shared::float4 e) {
    shared::IrradiancePayload p{};
    p.irradiance = e;
    return p;
}

// Synthetic records whose irradiance follows f(t) = 1 + b t + c t^2 / 2 (every channel, at
// several scales): the departure lifespan from E(0), E(1), E(2) never lets the line towards the
// replacement depart by more than a^t at a frame served, and is at most one frame shorter than
// the brute-force oracle's. A linear change (c = 0) serves delta t_max however fast it is, where
// the change's lifespan is short; a fast curvature serves one or two frames. (No c of the grid
// puts sqrt(8 a^t / |c|) on an integer, where rounding could go either way.)
TEST(TemporalCaching, DepartureLifespanAgainstTheChordByBruteForce) {
    TemporalOptions options;
    options.lifespan = TemporalLifespan::kDeparture;
    const shared::float4 scales[] = {{1.0f, 0.5f, 0.25f, 0.0f}, {40.0f, 3.0f, 0.2f, 0.0f}};
    int checked = 0;
    for (const shared::float4& s : scales) {
        for (double b : {-0.04, -0.01, 0.0, 0.003, 0.02, 0.1}) {
            for (double c : {-0.012, -0.002, 0.0, 0.0005, 0.003, 0.02, 0.3}) {
                shared::IrradiancePayload e[3];
                for (int t = 0; t < 3; ++t) {
                    const float f = static_cast<float>(quadratic(b, c, t));
                    e[t] = payload_of({s.x * f, s.y * f, s.z * f, 0.0f});
                }
                const float curvature = temporal_curvature(e[0], e[1], e[2]);
                const int given = departure_lifespan(curvature, options, false);
                const int oracle = oracle_departure_lifespan(b, c, options);
                EXPECT_LE(chord_departure(b, c, given), options.accuracy * 1.0001)
                    << "b " << b << " c " << c;
                EXPECT_GE(given, oracle - 1) << "b " << b << " c " << c;
                EXPECT_LE(given, oracle) << "b " << b << " c " << c;
                if (c == 0.0) {
                    EXPECT_EQ(given, options.max_frames) << "b " << b;
                }
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 84);
    // Linear and fast: the change's lifespan is one frame, the departure's the longest.
    const shared::IrradiancePayload a = payload_of({1.0f, 1.0f, 1.0f, 0.0f});
    const shared::IrradiancePayload b = payload_of({1.25f, 1.25f, 1.25f, 0.0f});
    const shared::IrradiancePayload c = payload_of({1.5f, 1.5f, 1.5f, 0.0f});
    EXPECT_EQ(temporal_lifespan(temporal_change(a, b), options, false), 1);
    EXPECT_EQ(departure_lifespan(temporal_curvature(a, b, c), options, false), options.max_frames);
    // A fast curvature: 1, 1.1, 1.5 (c = 0.3) serves one frame; a moving site serves one frame.
    const shared::IrradiancePayload d = payload_of({1.1f, 1.1f, 1.1f, 0.0f});
    EXPECT_EQ(departure_lifespan(temporal_curvature(a, d, c), options, false), 1);
    EXPECT_EQ(departure_lifespan(0.0f, options, true), 1);
}

// A point light alone in the closed box, its intensity I(t) = 4 f(t) at frames 0, 1, 2: every
// record's irradiance is proportional to it, so the truth is E(t) = E(0) f(t) exactly. The
// records on the floor reprojected one and two frames ahead (the kernels carrying each sample by
// the change of the light's unshadowed irradiance at its hit) give the curvature of f, and the
// departure lifespan the brute-force oracle's on f: linear growth (f = 1, 1.25, 1.5) serves
// delta t_max where the change's lifespan is one frame; f = 1, 1.0125, 1.03 (b = 0.01,
// c = 0.005) serves 5 frames, the change's 2.
TEST(TemporalCaching, DepartureLifespanOfALightGrowingLinearlyOrQuadratically) {
    struct Growth {
        double b, c;
        int departure, change;
    };
    TemporalOptions options;
    options.lifespan = TemporalLifespan::kDeparture;
    const std::vector<RecordSite> sites = floor_sites({{0.0f, 0.0f}, {-0.6f, 0.5f}, {0.7f, -0.4f}});
    for (const Growth& g : {Growth{0.25, 0.0, options.max_frames, 1}, Growth{0.01, 0.005, 5, 2}}) {
        std::vector<std::filesystem::path> scenes;
        for (int t = 0; t < 3; ++t) {
            char emitter[128];
            std::snprintf(emitter, sizeof emitter,
                          R"({"type": "point", "position": [0.2, 0.4, 0.1], "intensity": %.6f})",
                          4.0 * quadratic(g.b, g.c, t));
            scenes.push_back(box_scene("growth_" + std::to_string(t), "", emitter, kStill));
        }
        test::DeviceFrame now(test::load_scene_at_frame(scenes[0], 0));
        const Scene next = load_scene(scenes[1]);
        const Scene ahead = load_scene(scenes[2]);
        std::vector<CarriedRecord> one;
        std::vector<CarriedRecord> two;
        const auto e0 = records_at(now.frame(), sites, 1024, 5, 64, &next, &one);
        records_at(now.frame(), sites, 1024, 5, 64, &ahead, &two);
        const int oracle = oracle_departure_lifespan(g.b, g.c, options);
        EXPECT_EQ(oracle, g.departure);
        for (size_t i = 0; i < sites.size(); ++i) {
            const float curvature = temporal_curvature(e0[i], one[i].next, two[i].next);
            EXPECT_NEAR(curvature, g.c, 1e-4) << i;
            EXPECT_EQ(departure_lifespan(curvature, options, false), oracle) << i;
            EXPECT_EQ(temporal_lifespan(temporal_change(e0[i], one[i].next), options, false),
                      g.change)
                << i;
        }
    }
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// `radcache render SCENE args... -o dir/name####.exr --stats dir/name.json --quiet`; its stats.
nlohmann::json render_frames(const std::filesystem::path& scene, const std::filesystem::path& dir,
                             const std::string& name, std::vector<std::string> args) {
    std::vector<std::string> command = {"render", scene.string()};
    command.insert(command.end(), args.begin(), args.end());
    for (const std::string& a :
         {std::string("-o"), (dir / (name + "####.exr")).string(), std::string("--stats"),
          (dir / (name + ".json")).string(), std::string("--quiet")}) {
        command.push_back(a);
    }
    const test::CommandResult result = test::run_radcache(command);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return nlohmann::json::parse(read_file(dir / (name + ".json")));
}

std::filesystem::path frame_file(const std::filesystem::path& dir, const std::string& name,
                                 int frame) {
    char number[8];
    std::snprintf(number, sizeof number, "%04d", frame);
    return dir / (name + number + ".exr");
}

// The Cornell box (no animation) over frames 0-4 with --temporal: every frame is, every layer bit
// for bit, the single-frame `ic` render; frame 0 creates every record and the later frames reuse
// them all, computing, replacing and dropping none.
TEST(TemporalCaching, StaticSceneRendersFrameZerosImageEveryFrame) {
    const auto dir = test::scratch_dir("temporal_static");
    const auto scene = test::source_dir() / "scenes" / "cornell-box" / "scene.json";
    const std::vector<std::string> common = {"--method", "ic", "--width",   "24", "--height", "24",
                                             "--spp",    "2",  "--ic-rays", "256"};
    std::vector<std::string> single = common;
    single.insert(single.end(), {"-o", (dir / "single.exr").string(), "--quiet"});
    std::vector<std::string> command = {"render", scene.string()};
    command.insert(command.end(), single.begin(), single.end());
    ASSERT_EQ(test::run_radcache(command).exit_code, 0);
    std::vector<std::string> temporal = common;
    temporal.insert(temporal.end(), {"--temporal", "--frames", "0:4"});
    const nlohmann::json stats = render_frames(scene, dir, "t", temporal);
    const Image expected = read_image(dir / "single.exr");
    const size_t records = stats["frames"][0]["records"].get<size_t>();
    EXPECT_GT(records, 0u);
    for (int f = 0; f <= 4; ++f) {
        EXPECT_TRUE(same_pixels(read_image(frame_file(dir, "t", f)), expected)) << "frame " << f;
        const nlohmann::json& t = stats["frames"][f]["temporal"];
        EXPECT_EQ(t["records"].get<size_t>(), records) << f;
        EXPECT_EQ(t["created"].get<size_t>(), f == 0 ? records : 0u) << f;
        EXPECT_EQ(t["reused"].get<size_t>(), f == 0 ? 0u : records) << f;
        EXPECT_EQ(t["recomputed"].get<size_t>(), 0u) << f;
        EXPECT_EQ(t["dropped"].get<size_t>(), 0u) << f;
    }
}

// The indirect layer of the moving sphere's reference at `frame`, box filtered to 32 x 32.
Image moving_sphere_reference(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame%04d.exr", frame);
    const Image reference =
        read_image(test::source_dir() / "scenes" / "moving-sphere" / "reference" / name);
    return box_filtered(select_layers(reference, {"indirect"}), 8);
}

// Mean over pixels and channels of ((v_f - v_{f-1}) - (r_f - r_{f-1}))^2 / (r_f^2 + 0.01): the
// change between two frames against the references' change (the flicker measure of
// docs/temporal-caching.md).
double temporal_error(const Image& v0, const Image& v1, const Image& r0, const Image& r1) {
    double sum = 0.0;
    for (size_t i = 0; i < v1.pixels.size(); ++i) {
        const double d = (v1.pixels[i] - v0.pixels[i]) - (r1.pixels[i] - r0.pixels[i]);
        sum += d * d / (r1.pixels[i] * r1.pixels[i] + 0.01);
    }
    return sum / static_cast<double>(v1.pixels.size());
}

// The moving sphere's frames 0-5 at 32 x 32, 4 camera samples, 256 rays per record: with
// --temporal the indirect layer's relMSE against the references (box filtered) is at most 1.25x
// per-frame irradiance caching's on average and 2e-3 every frame (measured 7.2e-4 to 8.1e-4
// against 7.1e-4 to 8.6e-4 per frame); its flicker (temporal error, summed over the frames) is
// lower than per-frame caching's (measured 1.32e-3 against 1.40e-3); and the whole sequence is
// the same bit for bit when rendered again in other launch chunks and work-groups.
TEST(TemporalCaching, MovingSphereIsAccurateStableAndDeterministic) {
    const auto dir = test::scratch_dir("temporal_moving_sphere");
    const auto scene = test::source_dir() / "scenes" / "moving-sphere" / "scene.json";
    const std::vector<std::string> common = {
        "--method", "ic",        "--width", "32",       "--height", "32",     "--spp",
        "4",        "--ic-rays", "256",     "--frames", "0:5",      "--aovs", "beauty,indirect"};
    std::vector<std::string> temporal = common;
    temporal.push_back("--temporal");
    render_frames(scene, dir, "t", temporal);
    render_frames(scene, dir, "p", common);
    std::vector<std::string> chunked = temporal;
    chunked.insert(chunked.end(), {"--max-chunk", "1000", "--local-size", "8"});
    render_frames(scene, dir, "c", chunked);
    double temporal_sum = 0.0;
    double plain_sum = 0.0;
    double temporal_flicker = 0.0;
    double plain_flicker = 0.0;
    Image previous_t, previous_p, previous_r;
    for (int f = 0; f <= 5; ++f) {
        const Image t_file = read_image(frame_file(dir, "t", f));
        EXPECT_TRUE(same_pixels(t_file, read_image(frame_file(dir, "c", f)))) << "frame " << f;
        const Image t = select_layers(t_file, {"indirect"});
        const Image p = select_layers(read_image(frame_file(dir, "p", f)), {"indirect"});
        const Image r = moving_sphere_reference(f);
        const double t_error = image_error(t, r).relmse;
        const double p_error = image_error(p, r).relmse;
        std::printf("frame %d: indirect relMSE temporal %.4g, per frame %.4g\n", f, t_error,
                    p_error);
        EXPECT_LT(t_error, 2e-3) << f;
        temporal_sum += t_error;
        plain_sum += p_error;
        if (f > 0) {
            temporal_flicker += temporal_error(previous_t, t, previous_r, r);
            plain_flicker += temporal_error(previous_p, p, previous_r, r);
        }
        previous_t = t;
        previous_p = p;
        previous_r = r;
    }
    std::printf("temporal error summed over frames 1-5: temporal %.4g, per frame %.4g\n",
                temporal_flicker, plain_flicker);
    EXPECT_LT(temporal_sum, 1.25 * plain_sum);
    EXPECT_LT(temporal_flicker, plain_flicker);
}

// Bad temporal options: one line naming the option, exit status 2, no image.
TEST(TemporalCaching, BadOptionsAreRefusedByName) {
    const auto dir = test::scratch_dir("temporal_bad");
    const auto scene = (test::source_dir() / "scenes" / "cornell-box" / "scene.json").string();
    const std::string out = (dir / "x.exr").string();
    struct Case {
        std::vector<std::string> args;
        std::string names;
    };
    const std::vector<Case> cases = {
        {{"--method", "ic", "--temporal", "--temporal-gradients", "cubic"}, "--temporal-gradients"},
        {{"--method", "ic", "--temporal", "--temporal-accuracy", "0"}, "--temporal-accuracy"},
        {{"--method", "ic", "--temporal", "--temporal-max-frames", "0"}, "--temporal-max-frames"},
        {{"--method", "ic", "--temporal", "--temporal-moving-hits", "skip"},
         "--temporal-moving-hits"},
        {{"--method", "ic", "--temporal-moving-hits", "cache"}, "needs --temporal"},
        {{"--method", "ic", "--temporal-accuracy", "0.1"}, "needs --temporal"},
        {{"--method", "ic", "--temporal", "--cache-out", (dir / "c.bin").string()}, "--cache-out"},
        {{"--method", "ic", "--temporal", "--ic-ivg"}, "--ic-ivg"},
        {{"--method", "sdrc", "--temporal", "--temporal-lifespan", "departure"},
         "--temporal-lifespan"},
        {{"--method", "rc", "--temporal-accuracy", "0.1"}, "needs --temporal"},
        {{"--method", "rc", "--temporal", "--temporal-max-frames", "0"}, "--temporal-max-frames"},
        {{"--method", "pt", "--temporal"}, "--temporal"},
        {{"--method", "ic", "--temporal", "--temporal-lifespan", "curvature"},
         "--temporal-lifespan"},
        {{"--method", "ic", "--temporal-lifespan", "departure"}, "needs --temporal"},
        {{"--method", "ic", "--temporal", "--temporal-lifespan", "departure",
          "--temporal-gradients", "extrapolated"},
         "--temporal-lifespan"},
        {{"--method", "rc", "--temporal", "--temporal-lifespan", "departure"},
         "--temporal-lifespan"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> command = {"render",  scene, "-o",       out,
                                            "--width", "8",   "--height", "8"};
        command.insert(command.end(), c.args.begin(), c.args.end());
        const test::CommandResult result = test::run_radcache(command);
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find(c.names), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.names;
    }
}

}  // namespace
}  // namespace rc
