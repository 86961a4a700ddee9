// The radcache command line: what `render` and `bench rays` write, and a clear error with exit
// status 2 and no output file for every bad option.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>
#include <tuple>

#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::string cornell_box() {
    return (test::source_dir() / "scenes/cornell-box/scene.json").string();
}

std::string glossy_box() { return (test::source_dir() / "scenes/glossy-box/scene.json").string(); }

TEST(Cli, RenderWritesEachImageFormatAndStats) {
    const auto dir = test::scratch_dir("cli_render");
    for (const char* name : {"out.png", "out.exr", "out.hdr", "out.pfm"}) {
        const auto output = dir / name;
        const test::CommandResult result = test::run_radcache(
            {"render", cornell_box(), "-o", output.string(), "--width", "48", "--height", "32",
             "--spp", "2", "--quiet", "--stats", (dir / "stats.json").string()});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(result.output, "") << "--quiet prints nothing";
        const Image image = read_image(output);
        EXPECT_EQ(image.width, 48);
        EXPECT_EQ(image.height, 32);
        EXPECT_GE(image.channels, 3);
    }
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    EXPECT_EQ(stats["method"], "pt");
    EXPECT_EQ(stats["resolution"][0], 48);
    EXPECT_EQ(stats["spp"], 2);
    EXPECT_EQ(stats["triangles"], 38);
    EXPECT_TRUE(stats["kernels"].contains("path_trace_pass"));
    EXPECT_GT(stats["rays"].get<double>(), 48.0 * 32.0 * 2.0);
    EXPECT_EQ(stats["nonfinite_samples"], 0);
    EXPECT_GT(stats["seconds"]["total"].get<double>(), 0.0);
    // No temporary files are left behind.
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
            << entry.path();
    }
}

struct BadCommand {
    std::vector<std::string> args;
    int exit_code;
    std::string expected;
};

// --environment: a plane of reflectance 0.5 under a constant sky L reflects 0.5 L (its irradiance
// pi L). Without an emitter the scene gets that sky, and no "no emitter" warning; with a sky of
// its own the sky's radiance is replaced, not added to. The path tracer's mean of 16 x 16 pixels
// at 32 samples is within 0.3 % of it (one standard error): 3 % is 10.
TEST(Cli, EnvironmentLightsAnUnlitSceneAndReplacesItsSky) {
    const auto dir = test::scratch_dir("cli_environment");
    const std::string plane = R"({
        "camera": {"position": [0, 10, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 30,
                   "resolution": [16, 16]},
        "materials": {"ground": {"type": "diffuse", "reflectance": 0.5}},
        "shapes": [{"type": "rectangle", "material": "ground",
                    "transform": [{"scale": 5}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]}])";
    write_file_atomically(dir / "unlit.json", plane + "}");
    write_file_atomically(dir / "sky.json",
                          plane + R"(, "emitters": [{"type": "constant", "radiance": 7}]})");
    for (const auto& [scene, colour, expected] :
         {std::tuple<std::string, std::string, std::array<double, 3>>{
              "unlit", "1,0.5,0.25", {0.5, 0.25, 0.125}},
          {"sky", "2", {1.0, 1.0, 1.0}}}) {
        SCOPED_TRACE(scene);
        const auto image = dir / (scene + ".exr");
        const test::CommandResult result =
            test::run_radcache({"render", (dir / (scene + ".json")).string(), "-o", image.string(),
                                "--spp", "32", "--environment", colour});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        EXPECT_EQ(result.output.find("no emitter"), std::string::npos) << result.output;
        const Image beauty = read_image(image);
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0;
            for (int y = 0; y < beauty.height; ++y) {
                for (int x = 0; x < beauty.width; ++x) {
                    sum += beauty.at(x, y, c);
                }
            }
            EXPECT_NEAR(sum / (beauty.width * beauty.height), expected[c], 0.03 * expected[c])
                << "channel " << c;
        }
    }
    // Without it, the unlit scene is warned about, naming the way out.
    const test::CommandResult unlit =
        test::run_radcache({"render", (dir / "unlit.json").string(), "-o",
                            (dir / "black.png").string(), "--spp", "1"});
    EXPECT_NE(unlit.output.find("no emitter that gives light"), std::string::npos) << unlit.output;
    EXPECT_NE(unlit.output.find("--environment"), std::string::npos) << unlit.output;
}

// The bad commands, their paths under `dir`.
std::vector<BadCommand> bad_commands(const std::filesystem::path& dir) {
    const std::string out = (dir / "out.png").string();
    return {
        {{"render", cornell_box(), "-o", (dir / "out.xyz").string()}, 2, "unsupported output"},
        {{"render", cornell_box(), "-o", (dir / "missing/out.png").string()}, 2, "does not exist"},
        {{"render", cornell_box(), "-o", out, "--method", "no-such-method"},
         2,
         "unknown method 'no-such-method'"},
        {{"render", cornell_box(), "-o", out, "--bogus"}, 2, "unknown option '--bogus'"},
        {{"render", cornell_box(), "-o", out, "--spp", "0"}, 2, "--spp"},
        {{"render", cornell_box(), "-o", out, "--environment", "1,2"}, 2, "--environment"},
        {{"render", cornell_box(), "-o", out, "--environment", "-1"}, 2, "--environment"},
        {{"render", cornell_box(), "-o", out, "--environment", "nan,1,1"}, 2, "--environment"},
        {{"render", cornell_box(), "-o", out, "--environment", (dir / "sky.exr").string()},
         2,
         "or a lat-long image file, got"},
        {{"render", cornell_box(), "-o", out, "--width", "abc"}, 2, "--width"},
        {{"render", cornell_box(), "-o", out, "--width"}, 2, "needs a value"},
        {{"render", (dir / "nope.json").string(), "-o", out}, 1, "not found"},
        {{"render", "-o", out}, 2, "exactly one scene"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--accuracy", "0"},
         2,
         "--accuracy"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--accuracy", "1.5"},
         2,
         "--accuracy"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--ic-rays", "2"}, 2, "--ic-rays"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--ic-deeper-rays", "3"},
         2,
         "--ic-deeper-rays"},
        {{"render", cornell_box(), "-o", out, "--method", "pt", "--ic-deeper-rays", "64"},
         2,
         "--ic-deeper-rays"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--ic-bounces", "0"},
         2,
         "--ic-bounces"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--ic-min-spacing", "abc"},
         2,
         "--ic-min-spacing: expected a length"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--ic-max-spacing", "-2u"},
         2,
         "--ic-max-spacing"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--ic-min-spacing", "16",
          "--ic-max-spacing", "4"},
         2,
         "--ic-min-spacing exceeds --ic-max-spacing"},
        {{"render", cornell_box(), "-o", out, "--accuracy", "0.3"}, 2, "applies to --method ic"},
        {{"render", cornell_box(), "-o", out, "--dump-kernels", "/dev/null/kernels"},
         2,
         "--dump-kernels /dev/null/kernels: cannot make the folder ("},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--temporal", "--time", "3"},
         2,
         "--time: temporal caching renders --spp camera samples a frame"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--cache-in",
          (dir / "missing.rcc").string()},
         1,
         "irradiance cache file not found"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--cache-out",
          (dir / "nodir/cache.rcc").string()},
         2,
         "--cache-out"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--aovs", "stddev"},
         2,
         "has no layer 'stddev'"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--grid", "3x3"}, 2, "--grid"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--grid", "0x4x4"},
         2,
         "--grid: voxels per axis"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--ivg-interp", "cubic"},
         2,
         "--ivg-interp"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--photons", "0"}, 2, "--photons"},
        {{"render", cornell_box(), "-o", out, "--photons", "100"},
         2,
         "--photons applies to --method ic, ivg, ivg-gather or decomposition only"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--gather-rays", "4"},
         2,
         "--gather-rays applies to --method ivg-gather only"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg-gather", "--gather-rays", "0"},
         2,
         "--gather-rays"},
        {{"render", cornell_box(), "-o", out, "--ic-ivg"}, 2, "--ic-ivg applies"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--light-samples", "0"},
         2,
         "--light-samples: expected an integer in [1, 64], got '0'"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--light-samples", "-2"},
         2,
         "--light-samples: expected an integer"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg-gather", "--light-samples", "four"},
         2,
         "--light-samples: expected an integer"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--light-samples", "65"},
         2,
         "--light-samples: expected an integer in [1, 64], got '65'"},
        {{"render", cornell_box(), "-o", out, "--light-samples", "4"},
         2,
         "--light-samples applies to --method ic, rc, sdrc, ivg, ivg-gather or decomposition only"},
        {{"render", cornell_box(), "-o", out, "--method", "normals", "--light-samples", "4"},
         2,
         "--light-samples applies to --method ic, rc, sdrc, ivg, ivg-gather or decomposition only"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-order", "0"},
         2,
         "--rc-order: expected an integer in [1, 10], got '0'"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-order", "11"},
         2,
         "--rc-order: expected an integer in [1, 10], got '11'"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-order", "high"},
         2,
         "--rc-order: expected an integer"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-max-error", "0"},
         2,
         "--rc-max-error"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-max-error", "1.5"},
         2,
         "--rc-max-error"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-rays", "8"}, 2, "--rc-rays"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--accuracy", "2"},
         2,
         "--accuracy"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--rc-rays", "64"},
         2,
         "--rc-rays applies to --method rc only"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-cache-out",
          (dir / "nodir/rc.rcc").string()},
         2,
         "--rc-cache-out"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--rc-cache-in",
          (dir / "missing.rcc").string()},
         1,
         "radiance cache file not found"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--rc-cache-in",
          (dir / "missing.rcc").string()},
         2,
         "--rc-cache-in applies to --method rc only"},
        {{"render", cornell_box(), "-o", out, "--method", "sdrc", "--sdrc-interp", "0"},
         2,
         "--sdrc-interp: expected an integer in [1, 64], got '0'"},
        {{"render", cornell_box(), "-o", out, "--method", "sdrc", "--sdrc-samples", "8"},
         2,
         "--sdrc-samples: expected an integer in [16, 65536], got '8'"},
        {{"render", cornell_box(), "-o", out, "--method", "sdrc", "--sdrc-samples", "many"},
         2,
         "--sdrc-samples: expected an integer"},
        {{"render", cornell_box(), "-o", out, "--method", "sdrc", "--sdrc-max-radius", "0"},
         2,
         "--sdrc-max-radius"},
        {{"render", cornell_box(), "-o", out, "--method", "sdrc", "--sdrc-memory", "-1"},
         2,
         "--sdrc-memory"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--sdrc-interp", "4"},
         2,
         "--sdrc-interp applies to --method sdrc only"},
        {{"render", cornell_box(), "-o", out, "--method", "sdrc", "--ic-ivg"},
         2,
         "--ic-ivg applies to --method ic only"},
        {{"render", glossy_box(), "-o", out, "--method", "sdrc", "--width", "16", "--height", "16",
          "--spp", "1", "--sdrc-memory", "0.001"},
         1,
         "more than --sdrc-memory"},
        {{"render", cornell_box(), "-o", out, "--method", "rc", "--ic-ivg"},
         2,
         "--ic-ivg applies to --method ic only"},
        {{"render", cornell_box(), "-o", out, "--method", "ic", "--ic-ivg", "--ic-bounces", "2"},
         2,
         "needs --ic-bounces 1"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--grid-in",
          (dir / "missing.rcg").string()},
         1,
         "irradiance vector grid file not found"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--grid-in",
          (dir / "missing.rcg").string(), "--photons", "5"},
         2,
         "--photons and --grid-in"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--grid-out",
          (dir / "nodir/grid.rcg").string()},
         2,
         "--grid-out"},
        {{"render", cornell_box(), "-o", out, "--method", "ivg", "--aovs", "coverage"},
         2,
         "has no layer 'coverage'"},
        {{"render", cornell_box(), "-o", out, "--filter", "mitchell"},
         2,
         "--filter: expected box, tent or gaussian, got 'mitchell'"},
        {{"render", cornell_box(), "-o", out, "--filter", "tent", "--filter-radius", "0"},
         2,
         "--filter-radius: expected a number"},
        {{"render", cornell_box(), "-o", out, "--filter-radius", "17"}, 2, "--filter-radius"},
        {{"compare", (dir / "a.exr").string()}, 2, "TEST and REF"},
        {{"compare", (dir / "a.exr").string(), (dir / "b.exr").string()}, 1, "a.exr"},
        {{"compare", (dir / "a.exr").string(), (dir / "b.exr").string(), "--reference-spp", "0"},
         2,
         "--reference-spp"},
        {{"render", cornell_box(), "-o", out, "--bvh", "binary"},
         2,
         "--bvh: unknown BVH layout 'binary' (bvh4 or wide)"},
        {{"bench", "rays", "--bvh", "octree"}, 2, "--bvh: unknown BVH layout 'octree'"},
        {{"frobnicate"}, 2, "unknown command"},
        {{"bench", "nothing"}, 2, "unknown benchmark"},
        {{"devices", "extra"}, 2, "no arguments"},
        {{"render", cornell_box(), "-o", out, "--write-from", "2"},
         2,
         "--write-from 2 needs --frames"},
        {{"render", cornell_box(), "-o", (dir / "f####.exr").string(), "--frames", "0:3",
          "--write-from", "4"},
         2,
         "--write-from 4: not within --frames 0:3"},
        {{"render", cornell_box(), "-o", (dir / "f####.exr").string(), "--frames", "0:3",
          "--write-from", "two"},
         2,
         "--write-from: expected a frame number, got 'two'"},
        {{"render", cornell_box(), "-o", out, "--clip-end", "2"}, 2, "--clip-end 2 needs --frames"},
        {{"render", cornell_box(), "-o", (dir / "f####.exr").string(), "--frames", "0:3",
          "--clip-end", "2"},
         2,
         "--clip-end 2: before the last of --frames 0:3"},
    };
}

// The bad commands run as four tests, each a quarter of the list in its own folder: on Intel's
// runtime a command that reaches the device pays its start (seconds), and one test of them all
// outlasts the suite's bound under a loaded machine.
constexpr int kBadCommandQuarters = 4;

class BadCommands : public testing::TestWithParam<int> {};

TEST_P(BadCommands, FailClearlyWithoutOutput) {
    const int quarter = GetParam();
    const auto dir = test::scratch_dir("cli_bad_" + std::to_string(quarter));
    const std::vector<BadCommand> cases = bad_commands(dir);
    const size_t begin = cases.size() * quarter / kBadCommandQuarters;
    const size_t end = cases.size() * (quarter + 1) / kBadCommandQuarters;
    ASSERT_LT(begin, end);
    for (size_t i = begin; i < end; ++i) {
        const BadCommand& bad = cases[i];
        const test::CommandResult result = test::run_radcache(bad.args);
        std::string joined;
        for (const std::string& a : bad.args) {
            joined += a + " ";
        }
        EXPECT_EQ(result.exit_code, bad.exit_code) << joined << "\n" << result.output;
        EXPECT_NE(result.output.find(bad.expected), std::string::npos) << joined << "\n"
                                                                       << result.output;
        EXPECT_NE(result.output.find("radcache: error: "), std::string::npos) << result.output;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

INSTANTIATE_TEST_SUITE_P(Cli, BadCommands, testing::Range(0, kBadCommandQuarters));

// A render with the irradiance vector grid writes its layers and the grid's statistics, and a
// saved grid is reused bitwise.
TEST(Cli, IrradianceVectorGridRenderWritesLayersStatsAndGrids) {
    const auto dir = test::scratch_dir("cli_ivg");
    const std::string image = (dir / "ivg.exr").string();
    const std::string grid = (dir / "cornell.rcg").string();
    const test::CommandResult first = test::run_radcache({"render",
                                                          cornell_box(),
                                                          "-o",
                                                          image,
                                                          "--method",
                                                          "ivg-gather",
                                                          "--spp",
                                                          "1",
                                                          "--width",
                                                          "32",
                                                          "--height",
                                                          "32",
                                                          "--gather-rays",
                                                          "4",
                                                          "--grid",
                                                          "8x8x8",
                                                          "--photons",
                                                          "20000",
                                                          "--grid-out",
                                                          grid,
                                                          "--stats",
                                                          (dir / "stats.json").string(),
                                                          "--quiet"});
    ASSERT_EQ(first.exit_code, 0) << first.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    const nlohmann::json& frame = stats["frames"][0];
    EXPECT_EQ(stats["method"], "ivg-gather");
    EXPECT_EQ(frame["gather_rays"], 4);
    EXPECT_EQ(frame["grid"]["cells"], nlohmann::json({8, 8, 8}));
    EXPECT_EQ(frame["grid"]["photons"], 20000);
    EXPECT_GT(frame["grid"]["photons_per_second"].get<double>(), 0.0);
    EXPECT_EQ(frame["grid"]["grid_bytes"], 9 * 9 * 9 * 54 * 4);
    const Image written = read_image(image);
    std::vector<std::string> layers = layer_names(written);
    std::sort(layers.begin(), layers.end());  // OpenEXR stores channels by name
    EXPECT_EQ(layers, (std::vector<std::string>{"albedo", "beauty", "direct", "grid", "indirect",
                                                "normal"}));
    const std::string again = (dir / "again.exr").string();
    const test::CommandResult reused = test::run_radcache(
        {"render", cornell_box(), "-o", again, "--method", "ivg-gather", "--spp", "1", "--width",
         "32", "--height", "32", "--gather-rays", "4", "--grid-in", grid, "--quiet"});
    ASSERT_EQ(reused.exit_code, 0) << reused.output;
    EXPECT_EQ(read_image(again).pixels, written.pixels);
}

// An irradiance-cached render writes its layers and per-frame statistics: records per placement
// pass, rays per record, seconds per phase, cache memory.
TEST(Cli, IrradianceCacheRenderWritesLayersAndStats) {
    const auto dir = test::scratch_dir("cli_ic");
    const auto output = dir / "ic.exr";
    // One small view, rendered twice: with --cache-out, then with --cache-in.
    auto render = [&](const std::string& image, const std::string& stats,
                      const std::vector<std::string>& cache) {
        std::vector<std::string> args = {"render",
                                         cornell_box(),
                                         "-o",
                                         image,
                                         "--method",
                                         "ic",
                                         "--width",
                                         "48",
                                         "--height",
                                         "32",
                                         "--spp",
                                         "2",
                                         "--ic-rays",
                                         "64",
                                         "--ic-min-spacing",
                                         "4px",
                                         "--ic-max-spacing",
                                         "100u",
                                         "--quiet",
                                         "--stats",
                                         stats};
        args.insert(args.end(), cache.begin(), cache.end());
        return test::run_radcache(args);
    };
    const test::CommandResult result = render(output.string(), (dir / "stats.json").string(),
                                              {"--cache-out", (dir / "cache.rcc").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Image image = read_image(output);
    for (const char* layer :
         {"beauty", "direct", "indirect", "albedo", "normal", "coverage", "records"}) {
        EXPECT_NO_THROW(select_layers(image, {layer})) << layer;
    }
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    EXPECT_EQ(stats["method"], "ic");
    const nlohmann::json& frame = stats["frames"][0];
    EXPECT_GT(frame["records"].get<int>(), 0);
    EXPECT_EQ(frame["placement_passes"][0]["stride"], 16);
    EXPECT_GT(frame["rays_per_record"].get<double>(), 64.0);
    EXPECT_GT(frame["cache_bytes"].get<double>(), 0.0);
    for (const char* phase : {"gbuffer", "placement", "records", "insertion", "splatting"}) {
        EXPECT_TRUE(frame["seconds"].contains(phase)) << phase;
    }
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "cache.rcc"));

    // The cache serves another render of the same view: nothing left to place.
    const test::CommandResult reuse =
        render((dir / "again.exr").string(), (dir / "again.json").string(),
               {"--cache-in", (dir / "cache.rcc").string()});
    ASSERT_EQ(reuse.exit_code, 0) << reuse.output;
    const nlohmann::json again = nlohmann::json::parse(read_file(dir / "again.json"));
    int every_level = 0;  // the file holds every cache level (two by default)
    for (const nlohmann::json& level : frame["level_records"]) {
        every_level += level.get<int>();
    }
    EXPECT_EQ(frame["level_records"].size(), 2u);
    EXPECT_EQ(again["frames"][0]["loaded_records"], every_level);
    EXPECT_EQ(again["frames"][0]["records"], frame["records"]);
}

// `compare --reference-spp` on a 2 x 1 reference with a stddev layer, figures worked out by hand:
// beauty (1, 1, 1 | 0, 0, 0.5), per-sample stddev (0.4, 0.8, 1.2 | 0, 0.2, 0.1) at 4 spp, so
// Var(r) = stddev^2 / 4 = 0.04, 0.16, 0.36 | 0, 0.01, 0.0025 and the reference's noise term is the
// mean of Var(r) / (r^2 + 0.01); test (1, 2, 3 | 0, 0, 0) gives relMSE
// (1 / 1.01 + 4 / 1.01 + 0.25 / 0.26) / 6.
TEST(Cli, CompareSubtractsTheReferencesNoise) {
    const auto dir = test::scratch_dir("cli_compare_net");
    Image test(2, 1, 3);
    test.channel_names = {"R", "G", "B"};
    test.pixels = {1, 2, 3, 0, 0, 0};
    Image reference(2, 1, 6);
    reference.channel_names = {"R", "G", "B", "stddev.R", "stddev.G", "stddev.B"};
    reference.pixels = {1, 1, 1, 0.4f, 0.8f, 1.2f, 0, 0, 0.5f, 0, 0.2f, 0.1f};
    write_image(dir / "test.exr", test);
    std::filesystem::create_directories(dir / "with-stats");
    write_image(dir / "with-stats/reference.exr", reference);
    write_image(dir / "reference.exr", reference);
    const double relmse = (1.0 / 1.01 + 4.0 / 1.01 + 0.25 / 0.26) / 6.0;
    const auto var = [](double s) { return double(float(s)) * double(float(s)) / 4.0; };
    const double noise =
        ((var(0.4) + var(0.8) + var(1.2)) / 1.01 + var(0.2) / 0.01 + var(0.1) / (0.25 + 0.01)) /
        6.0;
    const auto run = [&](const std::filesystem::path& ref, std::vector<std::string> extra) {
        std::vector<std::string> args = {"compare", (dir / "test.exr").string(), ref.string(),
                                         "--json", (dir / "error.json").string()};
        args.insert(args.end(), extra.begin(), extra.end());
        const test::CommandResult result = test::run_radcache(args);
        EXPECT_EQ(result.exit_code, 0) << result.output;
        return std::make_pair(result.output, nlohmann::json::parse(read_file(dir / "error.json")));
    };
    // Given on the command line.
    const auto [given, given_json] = run(dir / "reference.exr", {"--reference-spp", "4"});
    EXPECT_NE(given.find("relMSE net of the reference's noise"), std::string::npos) << given;
    EXPECT_NEAR(given_json["relmse"].get<double>(), relmse, 1e-6);
    EXPECT_NEAR(given_json["reference_noise"].get<double>(), noise, 1e-6);
    EXPECT_NEAR(given_json["relmse_net"].get<double>(), relmse - noise, 1e-6);
    EXPECT_EQ(given_json["reference_spp"].get<double>(), 4.0);
    // Read from reference.stats.json beside the reference, as `render --stats` writes it.
    write_file_atomically(dir / "with-stats/reference.stats.json", "{\"spp\": 4}\n");
    const auto [read, read_json] = run(dir / "with-stats/reference.exr", {});
    EXPECT_NEAR(read_json["relmse_net"].get<double>(), relmse - noise, 1e-6) << read;
    // Unknown: a one-line note and null in the JSON, the other figures unchanged.
    const auto [unknown, unknown_json] = run(dir / "reference.exr", {});
    EXPECT_NE(unknown.find("not reported"), std::string::npos) << unknown;
    EXPECT_TRUE(unknown_json["relmse_net"].is_null());
    EXPECT_NEAR(unknown_json["relmse"].get<double>(), relmse, 1e-6);
    // --reference-spp with a reference that has no stddev layer, or a negative count.
    const test::CommandResult no_stddev =
        test::run_radcache({"compare", (dir / "test.exr").string(), (dir / "test.exr").string(),
                            "--reference-spp", "4"});
    EXPECT_EQ(no_stddev.exit_code, 2);
    EXPECT_NE(no_stddev.output.find("--reference-spp: " + (dir / "test.exr").string() +
                                    " has no stddev layer"),
              std::string::npos)
        << no_stddev.output;
    const test::CommandResult negative =
        test::run_radcache({"compare", (dir / "test.exr").string(),
                            (dir / "reference.exr").string(), "--reference-spp", "-3"});
    EXPECT_EQ(negative.exit_code, 2);
    EXPECT_NE(negative.output.find("--reference-spp"), std::string::npos) << negative.output;
}

// A reference at twice the test's resolution: box-filtered 2 x 2 first, its noise that of a mean
// of four pixels of 4 samples each (variance (s1^2 + ... + s4^2) / 16 / 4); a reference at a
// resolution that is no such multiple is refused.
TEST(Cli, CompareBoxFiltersAReferenceAtAMultipleOfTheResolution) {
    const auto dir = test::scratch_dir("cli_compare_box");
    Image test(1, 1, 3);
    test.channel_names = {"R", "G", "B"};
    test.pixels = {1, 2, 3};
    Image reference(2, 2, 6);
    reference.channel_names = {"R", "G", "B", "stddev.R", "stddev.G", "stddev.B"};
    // R 0, 1, 2, 1 (mean 1); G 1, 1, 1, 1 (mean 1); B 2, 2, 2, 2 (mean 2); stddev 1, 2, 0, 1.
    reference.pixels = {0, 1, 2, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 1, 2, 0, 0, 0, 1, 1, 2, 1, 1, 1};
    write_image(dir / "test.exr", test);
    write_image(dir / "reference.exr", reference);
    const test::CommandResult result = test::run_radcache(
        {"compare", (dir / "test.exr").string(), (dir / "reference.exr").string(),
         "--reference-spp", "4", "--json", (dir / "error.json").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("box-filtered 2 x 2"), std::string::npos) << result.output;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "error.json"));
    // Differences 0, 1, 1 against references 1, 1, 2.
    const double relmse = (0.0 + 1.0 / 1.01 + 1.0 / 4.01) / 3.0;
    const double variance = (1.0 + 4.0 + 0.0 + 1.0) / 16.0 / 4.0;  // every channel alike
    const double noise = (variance / 1.01 + variance / 1.01 + variance / 4.01) / 3.0;
    EXPECT_NEAR(j["relmse"].get<double>(), relmse, 1e-6);
    EXPECT_NEAR(j["reference_noise"].get<double>(), noise, 1e-6);
    EXPECT_EQ(j["reference_box_filter"].get<int>(), 2);
    Image odd(3, 2, 3);
    write_image(dir / "odd.exr", odd);
    const test::CommandResult refused =
        test::run_radcache({"compare", (dir / "test.exr").string(), (dir / "odd.exr").string()});
    EXPECT_NE(refused.exit_code, 0);
    EXPECT_NE(refused.output.find("test.exr"), std::string::npos) << refused.output;
}

TEST(Cli, HelpListsOptions) {
    const test::CommandResult render = test::run_radcache({"render", "--help"});
    EXPECT_EQ(render.exit_code, 0);
    EXPECT_NE(render.output.find("--device"), std::string::npos);
    EXPECT_NE(render.output.find("--spp"), std::string::npos);
    const test::CommandResult top = test::run_radcache({"--help"});
    EXPECT_EQ(top.exit_code, 0);
    EXPECT_NE(top.output.find("bench rays"), std::string::npos);
}

TEST(Cli, BenchRaysWritesTheDocumentedJson) {
    const auto dir = test::scratch_dir("cli_bench");
    const auto json_path = dir / "rays.json";
    const test::CommandResult result =
        test::run_radcache({"bench", "rays", "--scene", cornell_box(), "--width", "64", "--repeat",
                            "1", "--json", json_path.string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json report = nlohmann::json::parse(read_file(json_path));
    ASSERT_TRUE(report.is_array());
    ASSERT_EQ(report.size(), 1u);
    const nlohmann::json& entry = report[0];
    for (const char* key : {"device", "scene", "triangles", "threads"}) {
        EXPECT_TRUE(entry.contains(key)) << key;
    }
    EXPECT_EQ(entry["triangles"], 38);
    // Both BVH layouts, side by side.
    for (const char* layout : {"bvh4", "wide"}) {
        SCOPED_TRACE(layout);
        ASSERT_TRUE(entry["layouts"].contains(layout));
        const nlohmann::json& figures = entry["layouts"][layout];
        EXPECT_GT(figures["node_bytes"].get<double>(), 0.0);
        EXPECT_GT(figures["leaf_bytes"].get<double>(), 0.0);
        for (const char* name :
             {"coherent_closest", "coherent_any", "incoherent_closest", "incoherent_any"}) {
            ASSERT_TRUE(figures.contains(name)) << name;
            EXPECT_GT(figures[name]["device_mrays"].get<double>(), 0.0);
            EXPECT_GT(figures[name]["embree_mrays"].get<double>(), 0.0);
            EXPECT_GT(figures[name]["ratio"].get<double>(), 0.0);
            // Both tracers answer (almost) every ray the same way; ties at edges are rare.
            EXPECT_GT(figures[name]["agreement"].get<double>(), 0.99);
        }
    }
}

TEST(Cli, BenchAllMeasuresEveryFamilyOnTheDevice) {
    const auto dir = test::scratch_dir("cli_bench_all");
    const auto json_path = dir / "all.json";
    const test::CommandResult result = test::run_radcache(
        {"bench", "all", "--scene", cornell_box(), "--width", "32", "--height", "32", "--spp", "1",
         "--repeat", "1", "--device", "0:0", "--json", json_path.string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("hemisphere samples/s"), std::string::npos) << result.output;
    const nlohmann::json report = nlohmann::json::parse(read_file(json_path));
    ASSERT_EQ(report["devices"].size(), 1u);
    const nlohmann::json& device = report["devices"][0];
    EXPECT_FALSE(device.contains("error"));
    for (const char* key :
         {"coherent_closest_mrays", "coherent_any_mrays", "incoherent_closest_mrays",
          "incoherent_any_mrays", "embree_coherent_closest_mrays", "embree_incoherent_any_mrays",
          "path_samples_per_second", "path_tracing_mrays", "hemisphere_samples_per_second",
          "records_per_second", "shade_samples_per_second", "splat_samples_per_second",
          "gather_samples_per_second", "photons_per_second", "photon_crossings_per_second",
          "sh_coefficients_per_second", "rc_reflections_per_second", "ltree_queries_per_second",
          "sdrc_directions_per_second"}) {
        ASSERT_TRUE(device.contains(key)) << key;
        EXPECT_GT(device[key].get<double>(), 0.0) << key;
    }
    EXPECT_FALSE(report.contains("together"));  // one device: nothing to split
}

// With two devices (PoCL's POCL_DEVICES="pthread pthread"; skipped where PoCL gives one), bench
// all measures each device, then whole pt and ic renders and grid builds on each alone and on both
// together, and reports the ratios of the medians it prints.
TEST(Cli, BenchAllTimesSeveralDevicesTogether) {
    const std::string two = "POCL_DEVICES=pthread pthread";
    if (test::run_radcache({"devices"}, {two}).output.find("0:1") == std::string::npos) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("cli_bench_together");
    const auto json_path = dir / "all.json";
    const test::CommandResult result = test::run_radcache(
        {"bench", "all", "--scene", cornell_box(), "--width", "32", "--height", "32", "--spp", "1",
         "--photons", "4096", "--repeat", "1", "--device", "0:0,0:1", "--json", json_path.string()},
        {two});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("devices together"), std::string::npos) << result.output;
    const nlohmann::json report = nlohmann::json::parse(read_file(json_path));
    ASSERT_EQ(report["devices"].size(), 2u);
    ASSERT_TRUE(report.contains("together"));
    const nlohmann::json& together = report["together"];
    EXPECT_EQ(together["devices"], nlohmann::json({"0:0", "0:1"}));
    for (const char* key :
         {"path_samples_per_second", "ic_samples_per_second", "photons_per_second"}) {
        ASSERT_TRUE(together.contains(key)) << key;
        const nlohmann::json& f = together[key];
        ASSERT_EQ(f["alone"].size(), 2u) << key;
        const double a = f["alone"][0].get<double>();
        const double b = f["alone"][1].get<double>();
        EXPECT_GT(a, 0.0) << key;
        EXPECT_GT(b, 0.0) << key;
        EXPECT_GT(f["together"].get<double>(), 0.0) << key;
        EXPECT_DOUBLE_EQ(f["sum_alone"].get<double>(), a + b) << key;
        EXPECT_DOUBLE_EQ(f["together_over_sum"].get<double>(),
                         f["together"].get<double>() / (a + b))
            << key;
        EXPECT_DOUBLE_EQ(f["together_over_best"].get<double>(),
                         f["together"].get<double>() / std::max(a, b))
            << key;
    }
}

}  // namespace
}  // namespace rc

namespace rc {
namespace {

TEST(Cli, FramesWriteOneImagePerFrameThroughTheHashPattern) {
    const auto dir = test::scratch_dir("cli_frames");
    const std::string scene = (test::source_dir() / "scenes/moving-sphere/scene.json").string();
    const test::CommandResult result =
        test::run_radcache({"render", scene, "-o", (dir / "frame_####.png").string(), "--frames",
                            "3:5", "--spp", "1", "--width", "24", "--height", "24", "--quiet"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* name : {"frame_0003.png", "frame_0004.png", "frame_0005.png"}) {
        EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "frame_0002.png"));
    // Several frames without a pattern is an error before any rendering.
    const test::CommandResult bad = test::run_radcache(
        {"render", scene, "-o", (dir / "one.png").string(), "--frames", "0:2", "--spp", "1"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("####"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "one.png"));
}

// Renders the two largest frame numbers (--frames 2147483646:2147483647) with `options` into the
// scratch folder `name`: the loop ends after them, two images written, the last one's too.
void expect_the_largest_frames_end_the_loop(const std::string& name,
                                            const std::vector<std::string>& options) {
    const auto dir = test::scratch_dir(name);
    std::vector<std::string> args = {"render",   cornell_box(),
                                     "-o",       (dir / "f####.png").string(),
                                     "--frames", "2147483646:2147483647"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CommandResult result = test::run_radcache(args);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        files += entry.is_regular_file() ? 1 : 0;
    }
    EXPECT_EQ(files, 2u);
    EXPECT_TRUE(std::filesystem::exists(dir / "f2147483647.png"));
}

// The last representable frame ends the loop (a frame counter of the frames' own type would
// overflow past it and render forever).
TEST(Cli, FramesEndingAtTheLargestFrameNumberStop) {
    expect_the_largest_frames_end_the_loop(
        "cli_frames_max", {"--method", "normals", "--width", "4", "--height", "4", "-q"});
}

// Temporal caching places frames ahead of the one it shades (hooks.visit_frame): its own frame
// loop must stop at the largest frame number too (the frame range's overflow, in the merged code).
TEST(Cli, TemporalFramesEndingAtTheLargestFrameNumberStop) {
    expect_the_largest_frames_end_the_loop(
        "cli_temporal_frames_max", {"--method", "ic", "--temporal", "--ic-rays", "16", "--spp", "1",
                                    "--width", "8", "--height", "8", "-q"});
}

TEST(Cli, SaveEveryPowerOfTwoWritesIntermediateImages) {
    const auto dir = test::scratch_dir("cli_pow2");
    const test::CommandResult result =
        test::run_radcache({"render", cornell_box(), "-o", (dir / "out.exr").string(), "--spp", "8",
                            "--save-every-pow2", "--width", "16", "--height", "16", "--quiet"});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* name :
         {"out.spp1.exr", "out.spp2.exr", "out.spp4.exr", "out.spp8.exr", "out.exr"}) {
        EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
    }
    // The last intermediate image is the final one.
    const Image final_image = read_image(dir / "out.exr");
    const Image at_8 = read_image(dir / "out.spp8.exr");
    EXPECT_EQ(final_image.pixels, at_8.pixels);
}

TEST(Cli, DefinesOverrideRenderDefaultsAndStatsRecordThem) {
    const auto dir = test::scratch_dir("cli_defines");
    const test::CommandResult result =
        test::run_radcache({"render", cornell_box(), "-o", (dir / "out.exr").string(), "-D",
                            "spp=3", "-Dmax_depth=2", "-D", "seed=42", "--width", "16", "--height",
                            "16", "--quiet", "--stats", (dir / "stats.json").string()});
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / "stats.json"));
    EXPECT_EQ(stats["spp"], 3);
    EXPECT_EQ(stats["max_depth"], 2);
    EXPECT_EQ(stats["seed"], 42);
    // The command line's own options win over -D.
    const test::CommandResult both = test::run_radcache(
        {"render", cornell_box(), "-o", (dir / "out2.exr").string(), "-D", "spp=3", "--spp", "2",
         "--width", "8", "--height", "8", "--quiet", "--stats", (dir / "stats2.json").string()});
    ASSERT_EQ(both.exit_code, 0) << both.output;
    EXPECT_EQ(nlohmann::json::parse(read_file(dir / "stats2.json"))["spp"], 2);
}

// --dump-kernels makes its folder (and missing parents) before any work; a run refused after
// that removes them again, a run that renders keeps them with the expanded sources.
TEST(Cli, DumpKernelsFolderStaysOnlyWhenTheRunDoes) {
    const auto dir = test::scratch_dir("cli_dump_kernels");
    const test::CommandResult refused =
        test::run_radcache({"render", cornell_box(), "-o", (dir / "a.png").string(), "--method",
                            "nosuch", "--dump-kernels", (dir / "new/kernels").string()});
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "new")) << refused.output;
    const test::CommandResult rendered = test::run_radcache(
        {"render", cornell_box(), "-o", (dir / "b.png").string(), "--method", "pt", "--width", "8",
         "--height", "8", "--spp", "1", "-q", "--dump-kernels", (dir / "kept/kernels").string()});
    EXPECT_EQ(rendered.exit_code, 0) << rendered.output;
    ASSERT_TRUE(std::filesystem::is_directory(dir / "kept/kernels"));
    EXPECT_FALSE(std::filesystem::is_empty(dir / "kept/kernels"));
}

TEST(Cli, RenderBadInputsFailBeforeWritingAnything) {
    const auto dir = test::scratch_dir("cli_render_bad");
    const std::string out = (dir / "out.png").string();
    const std::vector<BadCommand> cases = {
        {{"render", cornell_box(), "-o", out, "--width", "60000", "--height", "60000"},
         2,
         "60000x60000"},
        {{"render", cornell_box(), "-o", out, "-D", "samples=4"}, 2, "samples"},
        {{"render", cornell_box(), "-o", out, "-D", "spp=lots"}, 2, "spp"},
        {{"render", cornell_box(), "-o", out, "--frames", "5:1"}, 2, "--frames"},
        {{"render", cornell_box(), "-o", out, "--aovs", "depth"}, 2, "depth"},
        {{"render", cornell_box(), "-o", "/proc/nonexistent/out.png"}, 2, "/proc/nonexistent"},
        {{"render", cornell_box(), "-o", "/proc/out.png"}, 2, "not writable"},
        {{"render", cornell_box(), "-o", out, "--stats", (dir / "no/such/dir.json").string()},
         2,
         "--stats"},
    };
    for (const BadCommand& bad : cases) {
        const test::CommandResult result = test::run_radcache(bad.args);
        EXPECT_EQ(result.exit_code, bad.exit_code) << result.output;
        EXPECT_NE(result.output.find(bad.expected), std::string::npos) << result.output;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace rc
