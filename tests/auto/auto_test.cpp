// `--method auto` through the command line (docs/auto.md): the per-material choice on scenes whose
// lobes say what serves them (a diffuse box; a Phong 10 000 near-mirror; a Phong 16 and a Phong
// 200 sphere; a static clip, a walkthrough and a clip whose every object moves fast), the rules for
// --spp without --time and for a budget too small for the pilot, a scene without emitters,
// --dry-run, --time kept, the same plan and image from the same seed and options, and a stale
// throughput file and one with an implausible figure each replaced once.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "glossy_scenes.h"
#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"
#include "timed_render.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::string cornell_box() {
    return (test::source_dir() / "scenes/cornell-box/scene.json").string();
}

// A diffuse box lit from above with a sphere of each given material (JSON) in a row.
std::string spheres_scene(const std::string& scratch, const std::vector<std::string>& materials,
                          const std::string& animation = "") {
    const auto dir = test::scratch_dir(scratch);
    std::string material_json = R"("white": {"type": "diffuse", "reflectance": 0.7},
        "red": {"type": "diffuse", "reflectance": [0.6, 0.1, 0.1]})";
    std::string spheres;
    for (size_t i = 0; i < materials.size(); ++i) {
        const std::string name = "m" + std::to_string(i);
        material_json += ",\n\"" + name + "\": " + materials[i];
        const double x = -0.5 + (materials.size() > 1 ? i / (materials.size() - 1.0) : 0.5);
        spheres += R"(, {"type": "sphere", "name": "ball)" + std::to_string(i) +
                   R"(", "center": [)" + std::to_string(x) + R"(, -0.6, 0], "radius": 0.35,
                   "material": ")" +
                   name + "\"}";
    }
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 0, -3.4], "look_at": [0, 0, 0], "fov": 42, "resolution": [24, 24]},
        "materials": {)" + material_json + R"(},
        "shapes": [
            {"type": "rectangle", "name": "floor", "material": "white",
             "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"translate": [0, -1, 0]}]},
            {"type": "rectangle", "name": "back", "material": "white",
             "transform": [{"rotate": {"axis": [0, 1, 0], "angle": 180}}, {"translate": [0, 0, 1]}]},
            {"type": "rectangle", "name": "left", "material": "red",
             "transform": [{"rotate": {"axis": [0, 1, 0], "angle": -90}}, {"translate": [1, 0, 0]}]},
            {"type": "rectangle", "name": "light", "material": "white",
             "emitter": {"type": "area", "radiance": 12},
             "transform": [{"scale": 0.3}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 0.99, 0]}]})" +
                                             spheres + "]" + animation + "}";
    return (dir / "scene.json").string();
}

// `render SCENE --method auto --dry-run` with `options`: the plan of its --stats (exit 0 asserted).
nlohmann::json dry_run(const std::string& scene, const std::string& scratch,
                       const std::vector<std::string>& options) {
    const auto dir = test::scratch_dir(scratch);
    std::vector<std::string> args = {
        "render", scene, "--method", "auto", "--dry-run", "--stats", (dir / "plan.json").string()};
    args.insert(args.end(), options.begin(), options.end());
    if (std::find(options.begin(), options.end(), "-o") == options.end()) {
        args.insert(args.end(), {"-o", (dir / "out.exr").string()});
    }
    const test::CommandResult result = test::run_radcache(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr")) << "a dry run writes no image";
    EXPECT_NE(result.output.find("auto: "), std::string::npos) << result.output;
    return nlohmann::json::parse(read_file(dir / "plan.json")).at("plan");
}

std::string server_of(const nlohmann::json& plan, const std::string& material) {
    for (const nlohmann::json& m : plan.at("materials")) {
        if (m.at("name") == material) {
            return m.at("server").get<std::string>();
        }
    }
    ADD_FAILURE() << "no material " << material << " in " << plan.dump();
    return "";
}

TEST(AutoChoice, ADiffuseSceneCachesEveryMaterialWithIrradianceCaching) {
    const nlohmann::json plan =
        dry_run(cornell_box(), "auto_diffuse", {"--spp", "4", "--width", "24", "--height", "24"});
    ASSERT_FALSE(plan.at("materials").empty());
    for (const nlohmann::json& m : plan.at("materials")) {
        EXPECT_EQ(m.at("server"), "ic") << m.dump();
    }
    EXPECT_EQ(plan.at("method"), "ic");
    EXPECT_EQ(plan.at("pilot").at("cache").at("run").get<std::string>().rfind("ic ", 0), 0u);
}

TEST(AutoChoice, ANearMirrorIsPathTraced) {
    const std::string scene = spheres_scene(
        "auto_mirror",
        {R"({"type": "phong", "diffuse": 0.02, "specular": 0.9, "exponent": 10000})"});
    const nlohmann::json plan = dry_run(scene, "auto_mirror_plan", {"--spp", "2"});
    EXPECT_EQ(server_of(plan, "m0"), "pt");
    EXPECT_EQ(server_of(plan, "white"), "ic");
    // Radiance caching's tables leave the whole lobe to Monte Carlo.
    for (const nlohmann::json& m : plan.at("materials")) {
        if (m.at("name") == "m0") {
            EXPECT_EQ(m.at("rc_fallback").get<double>(), 1.0);
        }
    }
}

TEST(AutoChoice, ABroadAndASharpGlossyLobeGetDifferentGlossyCaches) {
    const std::string scene =
        spheres_scene("auto_two_lobes",
                      {R"({"type": "phong", "diffuse": 0.2, "specular": 0.5, "exponent": 16})",
                       R"({"type": "phong", "diffuse": 0.2, "specular": 0.5, "exponent": 200})"});
    const nlohmann::json plan = dry_run(scene, "auto_two_lobes_plan", {"--spp", "2"});
    EXPECT_EQ(server_of(plan, "m0"), "rc");
    EXPECT_EQ(server_of(plan, "m1"), "sdrc");
    EXPECT_NE(plan.at("command").get<std::string>().find("--glossy"), std::string::npos)
        << plan.dump();
    // The plan renders: both caches in one ic render.
    const auto dir = test::scratch_dir("auto_two_lobes_render");
    const test::CommandResult result = test::run_radcache(
        {"render", scene, "--method", "auto", "--spp", "2", "-o", (dir / "out.exr").string(),
         "--stats", (dir / "stats.json").string(), "-q"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json frame =
        nlohmann::json::parse(read_file(dir / "stats.json")).at("frames").at(0);
    EXPECT_EQ(frame.at("auto").at("command"), plan.at("command"));
    // Radiance caching's tables come from the pilot, not built again.
    EXPECT_FALSE(frame.at("radiance_cache").at("tables_built").get<bool>()) << frame.dump();
    test::expect_finite_lit_beauty(dir / "out.exr");
}

TEST(AutoChoice, AStaticClipIsCachedOverTimeAFastOneIsNot) {
    const nlohmann::json still = dry_run(
        cornell_box(), "auto_still_clip",
        {"--spp", "2", "--width", "16", "--height", "16", "--frames", "0:3", "-o", "f####.exr"});
    EXPECT_TRUE(still.at("temporal").get<bool>()) << still.dump();
    EXPECT_NE(still.at("command").get<std::string>().find("--temporal"), std::string::npos);
    // Every sphere crosses the box in three frames.
    const std::string animation = R"(, "animation": {"frame_start": 0, "frame_end": 3, "tracks": [
        {"target": "shape:ball0", "keyframes": [{"frame": 0, "translate": [-1.2, 0, 0]},
                                                {"frame": 3, "translate": [1.2, 0, 0]}]},
        {"target": "shape:ball1", "keyframes": [{"frame": 0, "translate": [1.2, 0, 0]},
                                                {"frame": 3, "translate": [-1.2, 0, 0]}]}]})";
    const std::string fast = spheres_scene("auto_fast_clip",
                                           {R"({"type": "diffuse", "reflectance": 0.5})",
                                            R"({"type": "diffuse", "reflectance": 0.3})"},
                                           animation);
    const nlohmann::json moving =
        dry_run(fast, "auto_fast_clip_plan", {"--spp", "2", "--frames", "0:3", "-o", "f####.exr"});
    EXPECT_FALSE(moving.at("temporal").get<bool>()) << moving.dump();
    EXPECT_GT(moving.at("motion").get<double>(), still.at("motion").get<double>());
}

// The shipped walkthrough: nothing but the camera moves (from one room into the other), so the
// records' light does not change and the clip is cached over time.
TEST(AutoChoice, AWalkthroughOfAStillSceneIsCachedOverTime) {
    const std::string scene = (test::source_dir() / "scenes/walkthrough/scene.json").string();
    const nlohmann::json plan = dry_run(
        scene, "auto_walkthrough",
        {"--spp", "2", "--width", "16", "--height", "12", "--frames", "0:47", "-o", "f####.exr"});
    EXPECT_TRUE(plan.at("temporal").get<bool>()) << plan.dump();
    EXPECT_EQ(plan.at("motion").get<double>(), 0.0);
}

TEST(AutoRules, SppWithoutTimeFixesTheSamplesAndKeepsTheDefaultKnobs) {
    const nlohmann::json plan =
        dry_run(cornell_box(), "auto_spp", {"--spp", "8", "--width", "16", "--height", "16"});
    EXPECT_EQ(plan.at("spp").get<int>(), 8);
    EXPECT_EQ(plan.at("accuracy").get<double>(), 0.35);
    EXPECT_EQ(plan.at("ic_rays").get<int>(), 1024);
}

TEST(AutoRules, SppWithTimeFixesTheSamplesAndTheKnobsFitTheBudget) {
    const nlohmann::json plan =
        dry_run(cornell_box(), "auto_spp_time",
                {"--spp", "3", "--time", "20", "--width", "16", "--height", "16"});
    EXPECT_EQ(plan.at("spp").get<int>(), 3);
    EXPECT_LE(plan.at("predicted").at("seconds").get<double>() +
                  plan.at("pilot").at("seconds").get<double>(),
              20.0);
}

TEST(AutoRules, ABudgetTooSmallForThePilotIsRefused) {
    const auto dir = test::scratch_dir("auto_tiny_budget");
    const test::CommandResult result =
        test::run_radcache({"render", cornell_box(), "--method", "auto", "--time", "0.0001", "-o",
                            (dir / "out.exr").string(), "--width", "16", "--height", "16"});
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--time 0.0001: too short for --method auto"), std::string::npos)
        << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(AutoRules, ASceneWithoutEmittersIsWarnedAndRenders) {
    const auto dir = test::scratch_dir("auto_dark");
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 0, -3], "look_at": [0, 0, 0], "fov": 40, "resolution": [12, 12]},
        "shapes": [{"type": "cube"}]})";
    const test::CommandResult result =
        test::run_radcache({"render", (dir / "scene.json").string(), "--method", "auto", "--spp",
                            "2", "-o", (dir / "out.exr").string()});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("warning"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("emitter"), std::string::npos) << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.exr"));
}

TEST(AutoRules, ADryRunOfAnotherMethodSaysItHasNothingToPlan) {
    const auto dir = test::scratch_dir("auto_dry_pt");
    const test::CommandResult result =
        test::run_radcache({"render", cornell_box(), "--method", "pt", "--dry-run", "-o",
                            (dir / "out.exr").string(), "--width", "8", "--height", "8"});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("nothing to plan"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

// The plan without what measures the machine itself (the pilot's wall clock).
nlohmann::json plan_without_clock(nlohmann::json plan) {
    plan.at("pilot").erase("measured_seconds");
    plan.erase("throughput");
    return plan;
}

TEST(AutoDeterminism, TheSameSeedAndOptionsGiveTheSamePlanAndImage) {
    const auto dir = test::scratch_dir("auto_same");
    std::vector<nlohmann::json> plans;
    std::vector<Image> images;
    for (int run = 0; run < 2; ++run) {
        const std::string stats = (dir / ("stats" + std::to_string(run) + ".json")).string();
        const std::string out = (dir / ("out" + std::to_string(run) + ".exr")).string();
        const test::CommandResult result = test::run_radcache(
            {"render", cornell_box(), "--method", "auto", "--time", "8", "--width", "24",
             "--height", "24", "--seed", "5", "-o", out, "--stats", stats, "--quiet"});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        const nlohmann::json frame = nlohmann::json::parse(read_file(stats)).at("frames").at(0);
        plans.push_back(plan_without_clock(frame.at("auto")));
        images.push_back(read_image(out));
    }
    EXPECT_EQ(plans[0], plans[1]);
    EXPECT_TRUE(test::bitwise_equal(images[0], images[1]));
    // The layers every method auto may choose writes, whichever it chose.
    std::vector<std::string> layers = layer_names(images[0]);
    std::sort(layers.begin(), layers.end());
    EXPECT_EQ(layers,
              (std::vector<std::string>{"albedo", "beauty", "direct", "indirect", "normal"}));
}

// The pilot reads the path tracer's noise (v_pt, the relMSE of one sample) as two renders of 64
// samples per pixel at the pilot's size read it, on a scene whose glossy lobes and small light
// give samples far above their pixel's mean (the pixel's own noisy mean as the denominator read it
// 4 to 5 times low there).
TEST(AutoPilot, ThePathTracersNoiseIsReadAsManySamplesReadIt) {
    const std::string scene = (test::source_dir() / "scenes/glossy-box/scene.json").string();
    const nlohmann::json pilot =
        dry_run(scene, "auto_noise", {"--time", "1000", "--width", "256", "--height", "256"})
            .at("pilot");
    const auto dir = test::scratch_dir("auto_noise_check");
    Image images[2];
    const int spp = 64;
    for (int i = 0; i < 2; ++i) {
        const std::string out = (dir / ("pt" + std::to_string(i) + ".exr")).string();
        const test::CommandResult result = test::run_radcache(
            {"render", scene, "--method", "pt", "--spp", std::to_string(spp), "--seed",
             std::to_string(11 + i), "--width", std::to_string(pilot.at("width").get<int>()),
             "--height", std::to_string(pilot.at("height").get<int>()), "--aovs", "beauty", "-o",
             out, "--quiet"});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        images[i] = read_image(out);
    }
    // Var of one sample: spp (a - b)^2 / 2; the denominator the mean of 2 x 64 samples.
    double sum = 0.0;
    for (int y = 0; y < images[0].height; ++y) {
        for (int x = 0; x < images[0].width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double a = images[0].at(x, y, c);
                const double b = images[1].at(x, y, c);
                const double mean = 0.5 * (a + b);
                sum += spp * 0.5 * (a - b) * (a - b) / (mean * mean + 0.01);
            }
        }
    }
    const double v = sum / (3.0 * images[0].width * images[0].height);
    const double v_pt = pilot.at("v_pt").get<double>();
    EXPECT_GT(v_pt, v / 1.6) << "64-sample renders read " << v;
    EXPECT_LT(v_pt, v * 1.6) << "64-sample renders read " << v;
}

// A device's throughput file spoilt by `spoil` is measured again and replaced once, not measured
// again on every render. The kernel binaries are the suite's (hard links), the throughput file a
// copy of its own.
void expect_replaced_once(const std::string& scratch,
                          const std::function<void(nlohmann::json&)>& spoil) {
    dry_run(cornell_box(), scratch + "_warm", {"--spp", "1", "--width", "8", "--height", "8"});
    const std::filesystem::path shared = test::kernel_cache_dir();
    const auto dir = test::scratch_dir(scratch) / "cache";
    std::filesystem::create_directories(dir);
    // Every device's throughput file made stale (the suite's cache holds one per device it ran
    // on): the render's device measures again and rewrites its own.
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(shared)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("auto-throughput-", 0) == 0 && entry.path().extension() == ".json") {
            files.push_back(dir / name);
        } else {
            std::filesystem::copy(entry.path(), dir / name,
                                  std::filesystem::copy_options::recursive |
                                      std::filesystem::copy_options::create_hard_links);
        }
    }
    ASSERT_FALSE(files.empty()) << "the suite's cache holds no throughput file";
    for (const std::filesystem::path& file : files) {
        nlohmann::json stale = nlohmann::json::parse(read_file(shared / file.filename()));
        spoil(stale);
        std::ofstream(file) << stale.dump();
    }
    const std::vector<std::string> environment = {"RADCACHE_CACHE_DIR=" + dir.string()};
    std::vector<bool> measured;
    for (int run = 0; run < 2; ++run) {
        const auto stats = dir.parent_path() / ("plan" + std::to_string(run) + ".json");
        const test::CommandResult result =
            test::run_radcache({"render", cornell_box(), "--method", "auto", "--dry-run", "--spp",
                                "1", "--width", "8", "--height", "8", "--stats", stats.string()},
                               environment);
        ASSERT_EQ(result.exit_code, 0) << result.output;
        const nlohmann::json plan = nlohmann::json::parse(read_file(stats)).at("plan");
        measured.push_back(plan.at("throughput").at("measured_now").get<bool>());
    }
    EXPECT_EQ(measured, (std::vector<bool>{true, false}));
    const auto rewritten = std::count_if(files.begin(), files.end(), [&](const auto& file) {
        nlohmann::json own = nlohmann::json::parse(read_file(file));
        nlohmann::json spoilt = own;
        spoil(spoilt);
        return own != spoilt;  // spoiling it again changes it: it was measured anew
    });
    EXPECT_EQ(rewritten, 1) << "of " << files.size() << " throughput files";
}

// The file of an older radcache (without the BRDF tables' figure).
TEST(AutoThroughput, AnUnreadableCachedFileIsReplacedOnce) {
    expect_replaced_once("auto_stale",
                         [](nlohmann::json& file) { file.erase("table_seconds_per_material"); });
}

// A figure no device could measure (10^-300 s a ray would plan a million samples a pixel for a
// two-second budget).
TEST(AutoThroughput, AnImplausibleCachedFigureIsMeasuredAgain) {
    expect_replaced_once("auto_implausible",
                         [](nlohmann::json& file) { file["pt_seconds_per_ray"] = 1e-300; });
}

TEST(AutoTime, TheRenderKeepsToItsBudget) {
    const auto dir = test::scratch_dir("auto_time");
    // A first dry run measures the device's throughput if no earlier test has.
    dry_run(cornell_box(), "auto_time_warm", {"--spp", "1", "--width", "8", "--height", "8"});
    const double budget = 10.0;
    const test::CommandResult result = test::run_radcache(
        {"render", cornell_box(), "--method", "auto", "--time", "10", "--width", "32", "--height",
         "32", "-o", (dir / "out.exr").string(), "--stats", (dir / "stats.json").string(), "-q"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    const nlohmann::json& plan = stats.at("frames").at(0).at("auto");
    // The plan fits the budget by its own prediction; the render keeps to it within a generous
    // bound (the precise figures are tools/bench/auto.py's).
    EXPECT_LE(plan.at("predicted").at("seconds").get<double>() +
                  plan.at("pilot").at("seconds").get<double>(),
              budget);
    EXPECT_LT(stats.at("seconds").at("render").get<double>(), 4.0 * budget);
    test::expect_finite_lit_beauty(dir / "out.exr");
}

}  // namespace
}  // namespace rc
