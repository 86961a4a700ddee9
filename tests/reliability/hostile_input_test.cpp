// The hostile inputs of the first reliability probe, one regression test each: what crashed, hung,
// lost data, was silently wrong or gave a poor message, now refused (or warned about) with one
// clear line, the right exit status and no output file. The inputs the fuzzers found are in
// fuzz_regression_test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <glm/geometric.hpp>

#include "app/render_job.h"
#include "error_of.h"
#include "image/image.h"
#include "image/image_io.h"
#include "scene/json_parse.h"
#include "scene/obj_loader.h"
#include "scene/scene_loader.h"
#include "scratch_files.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

// One line (at most `longest` characters) holding every part.
void expect_line(const std::string& message, std::initializer_list<std::string> parts,
                 size_t longest = 400) {
    EXPECT_FALSE(message.empty()) << "no error";
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    EXPECT_LE(message.size(), longest) << message.substr(0, 500);
    for (const std::string& part : parts) {
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
}

const std::string kCamera =
    R"("camera": {"position": [0, 0, -5], "look_at": [0, 0, 0], "fov": 40, "resolution": [8, 8]})";
const std::string kLight = R"("emitters": [{"type": "point", "position": [0, 0, -4]}])";

std::string scene_of(const std::string& shapes, const std::string& extra = "") {
    return "{" + kCamera + ", " + kLight + ", \"shapes\": " + shapes +
           (extra.empty() ? "" : ", " + extra) + "}";
}

std::string load_error(const std::string& name, const std::string& text) {
    const auto dir = test::scratch_dir("hostile_" + name);
    const auto file = test::write_file(dir / "scene.json", text);
    return test::error_of([&] { load_scene(file); });
}

// Crashes: Embree's build asserted on world positions that overflow (checked in object space and
// on the upper 3x3 only). World positions are now checked after the transform and the divide by
// w, against the documented range.
TEST(HostileInput, WorldSpaceOverflowIsRefusedBeforeTheBvh) {
    // Each error names the shape (or emitter) by name and index, the vertex in object space and
    // the offending value: never the NaN of a divide by w = 0 (a follow-up of that probe: the error
    // printed "(-nan, -nan, -nan)").
    const auto expect_world_error = [](const std::string& message,
                                       std::initializer_list<std::string> parts) {
        expect_line(message, parts);
        EXPECT_EQ(message.find("nan"), std::string::npos) << message;
    };
    expect_world_error(
        load_error("huge_sphere", scene_of(R"([{"type": "sphere", "radius": 1e38}])")),
        {"scene.json", "shape 'sphere_0' (index 0): vertex 0 at (",
         "in object space, at frame 0: world z = -1e+38", "outside the world range"});
    expect_world_error(
        load_error("translate_twice", scene_of(R"([{"type": "cube"}, {"type": "cube", "transform": [
                                {"translate": [3e38, 0, 0]}, {"translate": [3e38, 0, 0]}]}])")),
        {"shape 'cube_1' (index 1): its transform at frame 0 overflows float (row 1, column 4 is "
         "infinite"});
    expect_world_error(
        load_error("zero_w", scene_of(R"([{"type": "cube", "transform": [{"matrix":
                    [1, 0, 0, 0,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, 0]}]}])")),
        {"shape 'cube_0' (index 0): vertex 0 at (",
         "its transform gives w = 0, no point in world space", "an affine one is 0 0 0 1"});
    expect_world_error(load_error("large_translate", scene_of(R"([{"type": "cube", "transform":
                    [{"translate": [0, 0, 2e12]}]}])")),
                       {"world z = 2e+12, outside the world range of +-1e12"});
    expect_world_error(
        load_error("far_emitter", "{" + kCamera + R"(, "shapes": [{"type": "cube"}], "emitters":
                   [{"type": "point", "position": [0, 5e12, -4]}]})"),
        {"emitter 'point_0' (index 0) at (0, 5e+12, -4) in object space",
         "world y = 5e+12, outside the world range"});
    // Just inside the range loads.
    EXPECT_EQ(load_error("inside", scene_of(R"([{"type": "cube", "transform":
                    [{"scale": 1e11}]}])")),
              "");
}

// Crashes: JSON nested 100 000 deep where a value is expected overflowed the stack while the
// error message serialised it.
TEST(HostileInput, DeepNestingIsRefusedAtItsDepth) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    expect_line(load_error("deep_shapes", scene_of(deep)),
                {"scene.json", "shapes", "nested deeper than 64 levels"});
    expect_line(load_error("deep_spp", scene_of("[]", "\"render\": {\"spp\": " + deep + "}")),
                {"scene.json", "render.spp", "nested deeper than 64 levels"});
    // 64 levels are fine for the parser (the scene then refuses the value by its type): the top
    // level, "render" and 62 arrays.
    const std::string sixty_four = std::string(62, '[') + std::string(62, ']');
    expect_line(load_error("deep_ok", scene_of("[]", "\"render\": {\"spp\": " + sixty_four + "}")),
                {"render: spp: expected an integer in [1, 16777216], got [[[["});
}

// Hangs: one OBJ face with 200 000 corners took quadratic time in triangulation (this test's
// CTest timeout is the hang detector); polygons are fanned in linear time, and those with more
// corners than tinyobjloader counts (255) before it reads them.
TEST(HostileInput, AHugePolygonLoadsInLinearTime) {
    const auto dir = test::scratch_dir("hostile_polygon");
    constexpr int kCorners = 200000;
    std::string obj;
    std::string face = "f";
    for (int i = 0; i < kCorners; ++i) {
        const double angle = 6.283185307179586 * i / kCorners;
        obj +=
            "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
        face += " " + std::to_string(i + 1);
    }
    // Between two small faces, with materials: the fan keeps its place and its material.
    const std::string text =
        "mtllib m.mtl\n" + obj + "usemtl a\nf 1 2 3\nusemtl b\n" + face + "\nusemtl a\nf 3 4 5\n";
    test::write_file(dir / "m.mtl", "newmtl a\nKd 0.5 0.5 0.5\nnewmtl b\nKd 0.2 0.2 0.2\n");
    const ObjData data = load_obj(test::write_file(dir / "disc.obj", text));
    ASSERT_EQ(data.mesh.triangles.size(), static_cast<size_t>(kCorners - 2 + 2));
    // A fan from corner 1: triangle k is (1, k + 2, k + 3).
    const auto position = [&](size_t t, int corner) {
        return data.mesh.positions[data.mesh.triangles[t][corner]];
    };
    EXPECT_EQ(position(1 + 5, 0), position(1, 0));
    EXPECT_EQ(position(1 + 5, 2), data.mesh.positions[data.mesh.triangles[1 + 6][1]]);
    ASSERT_EQ(data.materials.size(), 2u);
    EXPECT_EQ(data.mesh.materials[0], 0);
    EXPECT_EQ(data.mesh.materials[1], 1);
    EXPECT_EQ(data.mesh.materials[kCorners - 2], 1);
    EXPECT_EQ(data.mesh.materials[kCorners - 1], 0);
    // The last fan triangle closes the polygon: (1, n - 1, n).
    const size_t last = static_cast<size_t>(kCorners - 2);
    EXPECT_EQ(position(last, 0), position(1, 0));
    EXPECT_NEAR(position(last, 2).x, 1.0f, 1e-6f);  // corner n at angle 2 pi (n - 1) / n
}

// Hangs: `radcache compare /dev/zero REF` read /dev/zero forever.
TEST(HostileInput, OnlyRegularFilesAreRead) {
    const auto dir = test::scratch_dir("hostile_devices");
    const auto reference = dir / "ref.exr";
    write_image(reference, Image(2, 2, 3));
    const test::CommandResult compared =
        test::run_radcache({"compare", "/dev/zero", reference.string()});
    EXPECT_EQ(compared.exit_code, 1) << compared.output;
    expect_line(compared.output.substr(0, compared.output.size() - 1),
                {"/dev/zero", "not a regular file"});
    EXPECT_NE(test::error_of([] { read_file("/dev/zero"); }).find("not a regular file"),
              std::string::npos);
    // A mesh or an MTL library that is a device is refused before any allocation.
    test::write_file(dir / "m.obj",
                     "mtllib ../../../../../../../../../../dev/zero\nv 0 0 0\nv 1 0 0\n"
                     "v 0 1 0\nf 1 2 3\n");
    expect_line(test::error_of([&] { load_obj(dir / "m.obj"); }), {"zero", "not a regular file"});
    expect_line(load_error("device_mesh", scene_of(R"([{"type": "obj", "file":
                    "../../../../../../../../../../../dev/zero"}])")),
                {"not a regular file"});
}

// Data loss: an unwritable --stats (a directory) was found after the image had been written over
// the old one. It is now refused before any work, and nothing is written.
TEST(HostileInput, AnUnwritableStatsFileIsRefusedBeforeTheImage) {
    const auto dir = test::scratch_dir("hostile_stats");
    std::filesystem::create_directories(dir / "stats.json");
    const auto old_image = test::write_file(dir / "old.png", "old bytes");
    for (const std::string output : {"old.png", "new.png"}) {
        const test::CommandResult result = test::run_radcache(
            {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "-o",
             (dir / output).string(), "--stats", (dir / "stats.json").string(), "--method",
             "normals", "--width", "8", "--height", "8"});
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find("--stats"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("is a directory"), std::string::npos) << result.output;
    }
    EXPECT_EQ(read_file(old_image), "old bytes");
    EXPECT_FALSE(std::filesystem::exists(dir / "new.png"));
}

// Silently wrong: integers wrapped (resolution 4294967328 became 32, frame_start 4294967296
// became 0). Every integer is now read with a range check.
TEST(HostileInput, IntegersAreRangeCheckedNotWrapped) {
    std::string camera = kCamera;
    camera.replace(camera.find("[8, 8]"), 6, "[4294967328, 8]");
    expect_line(load_error("resolution",
                           "{" + camera + ", " + kLight + R"(, "shapes": [{"type": "cube"}]})"),
                {"camera.resolution", "[1, 65536]", "4294967328"});
    expect_line(load_error("frame_start",
                           scene_of(R"([{"type": "cube"}])",
                                    R"("animation": {"frame_start": 4294967296, "tracks": []})")),
                {"animation.frame_start", "4294967296", "2147483647"});
    expect_line(load_error("seed", scene_of(R"([{"type": "cube"}])",
                                            R"("render": {"seed": 18446744073709551615})")),
                {"render: seed", "18446744073709551615"});
}

// Silently wrong: MTL values were taken as tinyobjloader read them (nan as 0: a light silently
// off; an exponent outside the documented range accepted). They are checked as the scene's are,
// with the file and line.
TEST(HostileInput, MtlValuesAreValidatedWithFileAndLine) {
    const auto dir = test::scratch_dir("hostile_mtl");
    const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
    test::write_file(dir / "m.obj", obj);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"Kd nan 0.5 0.5", "'nan' is not finite"},
        {"Ke nan nan nan", "'nan' is not finite"},
        {"Ns -50", "Ns value -50 outside [0, 1e+06]"},
        {"Ns 1e30", "Ns value 1e30 outside [0, 1e+06]"},
        {"Kd 1.5 0 0", "Kd value 1.5 outside [0, 1]"},
        {"Ke -1 0 0", "Ke value -1 outside [0, 1e+09]"},
        {"Ks", "Ks has no value"},
    };
    for (const auto& [line, expected] : cases) {
        test::write_file(dir / "m.mtl", "# a material\nnewmtl a\n" + line + "\n");
        expect_line(test::error_of([&] { load_obj(dir / "m.obj"); }), {"m.mtl:3:", expected});
    }
}

// Silently wrong: a key given twice in one object took the last value.
TEST(HostileInput, DuplicateKeysAreRefused) {
    std::string camera = kCamera;
    camera.replace(camera.find("\"fov\": 40"), 9, "\"fov\": 40, \"fov\": 90");
    expect_line(load_error("duplicate",
                           "{" + camera + ", " + kLight + R"(, "shapes": [{"type": "cube"}]})"),
                {"scene.json", "camera.fov", "key given twice"});
    expect_line(test::error_of([] { parse_json(R"({"a": [{"b": 1, "b": 2}]})", "x.json"); }),
                {"x.json", "a[0].b", "key given twice"});
}

// A 4 x 2 RGB image of distinct finite values.
Image finite_image() {
    Image image(4, 2, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = 0.25f + 0.01f * static_cast<float>(i);
    }
    return image;
}

struct NanCompare {
    test::CommandResult refused;  // as it is
    test::CommandResult allowed;  // with --allow-nan
};

// The command `compare` (its --json `json`) over images with NaN pixels: refused with exit status 1
// and no JSON; then run with --allow-nan.
NanCompare compare_refused_then_allowed(std::vector<std::string> compare,
                                        const std::filesystem::path& json) {
    NanCompare result;
    result.refused = test::run_radcache(compare);
    EXPECT_EQ(result.refused.exit_code, 1) << result.refused.output;
    EXPECT_FALSE(std::filesystem::exists(json));
    compare.push_back("--allow-nan");
    result.allowed = test::run_radcache(compare);
    return result;
}

// Silently wrong: compare of an image with NaN pixels exited 0 with "psnr inf". NaN and infinite
// pixels are counted, and the command fails unless --allow-nan takes the figures over the rest.
TEST(HostileInput, CompareCountsNanPixels) {
    const auto dir = test::scratch_dir("hostile_compare_nan");
    const Image reference = finite_image();
    Image test_image = reference;
    test_image.at(1, 0, 2) = std::numeric_limits<float>::quiet_NaN();
    test_image.at(3, 1, 0) = std::numeric_limits<float>::infinity();
    test_image.at(0, 1, 1) += 0.5f;
    write_image(dir / "ref.exr", reference);
    write_image(dir / "test.exr", test_image);
    const auto [refused, accepted] = compare_refused_then_allowed(
        {"compare", (dir / "test.exr").string(), (dir / "ref.exr").string(), "--json",
         (dir / "e.json").string()},
        dir / "e.json");
    EXPECT_NE(refused.output.find("nonfinite pixels (NaN or infinite): 2 in TEST, 0 in REF"),
              std::string::npos)
        << refused.output;
    EXPECT_NE(
        refused.output.find("error: " + (dir / "test.exr").string() + ": 2 NaN or infinite pixels"),
        std::string::npos)
        << refused.output;
    EXPECT_EQ(refused.output.find("psnr inf"), std::string::npos) << refused.output;
    EXPECT_EQ(accepted.exit_code, 0) << accepted.output;
    // Over the 6 finite pixels: one value off by 0.5 among 18.
    const double rmse = std::sqrt(0.25 / 18.0);
    char expected[64];
    std::snprintf(expected, sizeof expected, "rmse %.6g ", rmse);
    EXPECT_NE(accepted.output.find(expected), std::string::npos) << accepted.output;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "e.json"));
    EXPECT_EQ(j["nonfinite_pixels"]["test"], 2);
    EXPECT_EQ(j["pixels"], 6);
}

// The same for a frame sequence (compare --frames, merged after the fix): a NaN pixel in any
// frame fails the command naming that frame's file; --allow-nan takes every frame's figures and
// every pair's temporal error over the pixels finite in both images.
TEST(HostileInput, CompareFramesCountsNanPixels) {
    const auto dir = test::scratch_dir("hostile_compare_frames_nan");
    const Image reference = finite_image();
    Image with_nan = reference;
    with_nan.at(2, 1, 0) = std::numeric_limits<float>::quiet_NaN();
    for (int frame = 0; frame < 3; ++frame) {
        const std::string n = std::to_string(frame);
        write_image(dir / ("ref" + n + ".exr"), reference);
        write_image(dir / ("test" + n + ".exr"), frame == 1 ? with_nan : reference);
    }
    const auto [refused, accepted] = compare_refused_then_allowed(
        {"compare", "--frames", "0:2", (dir / "test#.exr").string(), (dir / "ref#.exr").string(),
         "--json", (dir / "e.json").string()},
        dir / "e.json");
    EXPECT_NE(refused.output.find("error: " + (dir / "test1.exr").string() +
                                  ": 1 NaN or infinite pixels (0 in "),
              std::string::npos)
        << refused.output;
    ASSERT_EQ(accepted.exit_code, 0) << accepted.output;
    const nlohmann::json j = nlohmann::json::parse(read_file(dir / "e.json"));
    EXPECT_EQ(j["frames"][1]["nonfinite_pixels"]["test"], 1);
    EXPECT_EQ(j["frames"][1]["pixels"], 7);
    EXPECT_EQ(j["frames"][0]["pixels"], 8);
    // Identical finite pixels: every figure is 0, not NaN.
    for (const auto& frame : j["frames"]) {
        EXPECT_EQ(frame["relmse"], 0.0) << frame;
    }
    EXPECT_EQ(j["frames"][1]["temporal_error"], 0.0);
    EXPECT_EQ(j["frames"][2]["temporal_error"], 0.0);
    EXPECT_EQ(j["frames"][2]["temporal_pixels"], 7);
}

// Silently wrong: -o with 40 '#' wrote every frame to one file (a 32-byte buffer).
TEST(HostileInput, LongFramePatternsNameEveryFrame) {
    const std::string pattern = "f" + std::string(40, '#') + ".png";
    EXPECT_EQ(frame_path(pattern, 7).string(), "f" + std::string(39, '0') + "7.png");
    EXPECT_EQ(frame_path(pattern, -7).string(), "f-" + std::string(38, '0') + "7.png");
    EXPECT_NE(frame_path(pattern, 7), frame_path(pattern, 8));
    EXPECT_EQ(frame_path("f##.png", 2147483647).string(), "f2147483647.png");
}

// Silently wrong: a camera at 3e38 looking at -3e38 rendered black without a word; so did a scene
// with no emitter. Both warn, and --strict makes the warning an error.
TEST(HostileInput, BlackRendersAreWarnedAndStrictRefusesThem) {
    const auto dir = test::scratch_dir("hostile_black");
    const auto far_camera = test::write_file(
        dir / "far.json",
        scene_of(R"([{"type": "cube"}])")
            .replace(1, kCamera.size(),
                     R"("camera": {"position": [3e38, 0, 0], "look_at": [-3e38, 0, 0], "fov": 40,
                          "resolution": [8, 8]})"));
    const auto dark =
        test::write_file(dir / "dark.json", "{" + kCamera + R"(, "shapes": [{"type": "cube"}]})");
    for (const auto& [scene, expected] : std::vector<std::pair<std::filesystem::path, std::string>>{
             {far_camera, "camera at frame 0"}, {dark, "no emitter"}}) {
        const std::vector<std::string> args = {
            "render", scene.string(), "-o", (dir / "out.png").string(), "--method", "normals"};
        const test::CommandResult warned = test::run_radcache(args);
        EXPECT_EQ(warned.exit_code, 0) << warned.output;
        EXPECT_NE(warned.output.find("warning: "), std::string::npos) << warned.output;
        EXPECT_NE(warned.output.find(expected), std::string::npos) << warned.output;
        std::filesystem::remove(dir / "out.png");
        std::vector<std::string> strict = args;
        strict.push_back("--strict");
        const test::CommandResult refused = test::run_radcache(strict);
        EXPECT_EQ(refused.exit_code, 1) << refused.output;
        EXPECT_NE(refused.output.find(expected), std::string::npos) << refused.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    }
}

// Messages: `--frames 99999999999:...` printed "error: stoi" with exit status 1.
TEST(HostileInput, OutOfRangeFramesAreABadCommandLine) {
    const test::CommandResult result = test::run_radcache(
        {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "--frames",
         "99999999999:99999999999"});
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_EQ(result.output.find("stoi"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("--frames 99999999999:99999999999: frame 99999999999 outside "
                                 "[-2147483647, 2147483647]"),
              std::string::npos)
        << result.output;
}

// Messages: `--device all` on a machine of one device was refused as naming several; a device
// index past int printed "error: stoi"; a folder or /dev/zero given as a cache was "not found";
// `--filter-radius 0.001`, the documented least radius, was refused.
TEST(HostileInput, DeviceCacheAndBoundMessagesSayWhatIsWrong) {
    const auto dir = test::scratch_dir("hostile_messages");
    const std::string scene = (test::source_dir() / "scenes/cornell-box/scene.json").string();
    const std::string out = (dir / "out.png").string();
    const auto render = [&](std::vector<std::string> options) {
        std::vector<std::string> args = {"render", scene, "--width", "8",  "--height", "8",
                                         "--spp",  "1",   "-q",      "-o", out};
        args.insert(args.end(), options.begin(), options.end());
        return test::run_radcache(args);
    };
    const test::CommandResult all = render({"--device", "all"});
    EXPECT_EQ(all.exit_code, 0) << all.output;
    EXPECT_EQ(render({"--filter", "tent", "--filter-radius", "0.001"}).exit_code, 0);
    std::filesystem::remove(out);
    const std::vector<std::pair<std::vector<std::string>, std::string>> refused = {
        {{"--device", "0:99999999999"}, "no OpenCL device matches --device '0:99999999999'"},
        {{"--method", "ic", "--cache-in", dir.string()}, "is not a regular file"},
        {{"--method", "ic", "--cache-in", "/dev/zero"}, "is not a regular file"},
    };
    for (const auto& [options, expected] : refused) {
        const test::CommandResult result = render(options);
        EXPECT_NE(result.exit_code, 0) << result.output;
        EXPECT_EQ(result.output.find("stoi"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << expected;
    }
}

// Messages: an OBJ whose material library is missing gave three warnings, two in
// tinyobjloader's words ("Failed to load material file(s). Use default material.", "material [
// 'a' ] not found in .mtl"); now one line naming the library and the materials it would hold.
TEST(HostileInput, AMissingMaterialLibraryIsOneWarning) {
    const auto dir = test::scratch_dir("hostile_missing_mtl");
    std::ofstream(dir / "m.obj") << "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 2\n";
    std::ofstream(dir / "s.json")
        << R"({"camera": {"position": [0.3, 0.3, 2], "look_at": [0.3, 0.3, 0], "fov": 40,
                          "resolution": [8, 8]},
              "shapes": [{"type": "obj", "file": "m.obj"}],
              "emitters": [{"type": "point", "position": [0, 0, 2], "intensity": [1, 1, 1]}]})";
    const test::CommandResult result =
        test::run_radcache({"render", (dir / "s.json").string(), "--method", "normals", "-o",
                            (dir / "out.png").string()});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("m.obj: material library '"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("missing.mtl' not found: its materials 'a', 'b' get the default "
                                 "material"),
              std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("Failed to load"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("not found in .mtl"), std::string::npos) << result.output;
}

// Messages: an unusable $XDG_CACHE_HOME, where PoCL keeps its kernel cache and without which
// its platform does not load, was reported as "install an OpenCL driver". Where another
// implementation loads all the same (Intel's runtime), there is nothing to report.
TEST(HostileInput, AnUnusableCacheHomeIsNamedWhenNoPlatformLoads) {
    const test::CommandResult result =
        test::run_radcache({"devices"}, {"XDG_CACHE_HOME=/dev/null/cache"});
    if (result.exit_code == 0) {
        EXPECT_EQ(result.output.find("Portable Computing Language"), std::string::npos)
            << "PoCL loaded with an unusable cache folder: " << result.output;
        return;
    }
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("$XDG_CACHE_HOME (/dev/null/cache) is not a writable folder"),
              std::string::npos)
        << result.output;
}

// Messages: a bad numeric option was refused only after the scene had loaded, so the scene's own
// notes ("dropped 192 degenerate triangles") came before the error line. Every value that does
// not depend on the scene is now checked first: the error is the only line.
TEST(HostileInput, BadOptionsAreTheOnlyLine) {
    const auto dir = test::scratch_dir("hostile_bad_options");
    const std::string scene = (test::source_dir() / "scenes/moving-sphere/scene.json").string();
    const std::vector<std::vector<std::string>> bad = {
        {"--spp", "99999999999"}, {"--width", "-1"},
        {"--seed", "1e3"},        {"--exposure", "nan"},
        {"--local-size", "0"},    {"--device-memory", "0"},
        {"--method", "nope"},     {"--method", "pt", "--ic-rays", "16"}};
    for (const std::vector<std::string>& options : bad) {
        std::vector<std::string> args = {"render", scene, "-o", (dir / "out.png").string()};
        args.insert(args.end(), options.begin(), options.end());
        const test::CommandResult result = test::run_radcache(args);
        SCOPED_TRACE(options[0] + " " + options[1]);
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_EQ(result.output.find("dropped"), std::string::npos) << result.output;
        EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    }
}

// Messages: "fov": 1e400 gave the library's raw exception without the file or the key.
TEST(HostileInput, NumbersOutOfRangeNameTheFileAndPosition) {
    std::string camera = kCamera;
    camera.replace(camera.find("\"fov\": 40"), 9, "\"fov\": 1e400");
    const std::string message = load_error(
        "fov_overflow", "{\n" + camera + ", " + kLight + R"(, "shapes": [{"type": "cube"}]})");
    expect_line(message, {"scene.json: malformed JSON: at line 2, column", "1e400"});
    EXPECT_EQ(message.find("[json.exception"), std::string::npos) << message;
}

// An 8-bit RGB PNG that claims width x height pixels and holds none (an empty zlib stream).
std::string png_header(uint32_t width, uint32_t height) {
    auto crc32 = [](const std::string& bytes) {
        uint32_t crc = 0xffffffffu;
        for (const unsigned char byte : bytes) {
            crc ^= byte;
            for (int k = 0; k < 8; ++k) {
                crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
            }
        }
        return crc ^ 0xffffffffu;
    };
    auto be32 = [](uint32_t v) {
        return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16),
                           static_cast<char>(v >> 8), static_cast<char>(v)};
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        return be32(static_cast<uint32_t>(data.size())) + type + data + be32(crc32(type + data));
    };
    const std::string ihdr = be32(width) + be32(height) + std::string("\x08\x02\x00\x00\x00", 5);
    const std::string empty_zlib("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", empty_zlib) +
           chunk("IEND", "");
}

// Messages: a 74-byte PNG claiming 60000x60000 pixels printed only std::bad_alloc.
TEST(HostileInput, ImagesLargerThanTheLimitAreRefusedBeforeAllocation) {
    const auto dir = test::scratch_dir("hostile_png_size");
    const auto png = test::write_file(dir / "huge.png", png_header(60000, 60000));
    EXPECT_LT(read_file(png).size(), 80u);
    expect_line(test::error_of([&] { read_image(png); }),
                {"huge.png", "60000x60000", "more than the limit of 134217728 pixels"});
    const auto scene = test::write_file(
        dir / "scene.json", scene_of(R"([{"type": "cube", "material": "t"}])",
                                     R"("materials": {"t": {"type": "diffuse", "reflectance":
                                          {"type": "bitmap", "filename": "huge.png"}}})"));
    expect_line(test::error_of([&] { load_scene(scene); }), {"huge.png", "60000x60000"});
}

// Messages: a 50 MB string value was echoed whole into the error line.
TEST(HostileInput, ErrorLinesQuoteLongValuesShort) {
    const std::string long_text(50 << 20, 'x');
    // The file's path (some 60 characters here), the key, the rule and at most about 80
    // characters of the value.
    expect_line(load_error("long_type", scene_of("[{\"type\": \"" + long_text + "\"}]")),
                {"shapes[0].type"}, 260);
    expect_line(load_error("long_key", scene_of("[]", "\"" + long_text + "\": 1")), {"unknown key"},
                400);
    expect_line(
        load_error("long_spp", scene_of("[]", "\"render\": {\"spp\": \"" + long_text + "\"}")),
        {"render: spp"}, 260);
}

// Messages: a corrupt PNG printed libpng's own line before radcache's; the library's words now
// go into radcache's one line.
TEST(HostileInput, LibraryChatterJoinsTheOneErrorLine) {
    const auto dir = test::scratch_dir("hostile_png_corrupt");
    Image image(16, 16, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = static_cast<float>(i % 7) / 7.0f;
    }
    write_image(dir / "good.png", image);
    std::string bytes = read_file(dir / "good.png");
    const size_t data = bytes.find("IDAT");
    ASSERT_NE(data, std::string::npos);
    for (size_t i = data + 8; i < data + 40 && i < bytes.size(); ++i) {
        bytes[i] = static_cast<char>(bytes[i] ^ 0x5a);
    }
    const auto bad = test::write_file(dir / "bad.png", bytes);
    const test::CommandResult result =
        test::run_radcache({"compare", bad.string(), (dir / "good.png").string()});
    EXPECT_EQ(result.exit_code, 1) << result.output;
    ASSERT_FALSE(result.output.empty());
    EXPECT_EQ(result.output.rfind("radcache: error: ", 0), 0u) << result.output;
    EXPECT_EQ(result.output.find('\n'), result.output.size() - 1) << result.output;
    EXPECT_NE(result.output.find("bad.png"), std::string::npos) << result.output;
    // libpng's line joins only when it adds to OpenImageIO's (which repeats it as "PNG read
    // error: ..."); the reader's own newlines become "; ", never an escaped "\\n".
    const size_t chatter = result.output.find("libpng error: ");
    if (chatter != std::string::npos) {
        const std::string said =
            result.output.substr(chatter + 14, result.output.size() - 15 - chatter);
        EXPECT_EQ(result.output.find(said), chatter + 14) << result.output;
    }
    EXPECT_EQ(result.output.find("\\n"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace rc

namespace rc {
namespace {

size_t files_in(const std::filesystem::path& dir) {
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        files += entry.is_regular_file() ? 1 : 0;
    }
    return files;
}

test::CommandResult render_frames(const std::string& scene, const std::string& frames,
                                  const std::filesystem::path& dir, bool strict = false) {
    std::vector<std::string> args = {
        "render",   (test::source_dir() / "scenes" / scene / "scene.json").string(),
        "--frames", frames,
        "-o",       (dir / "f####.png").string(),
        "--method", "normals",
        "--width",  "4",
        "--height", "4",
        "-q"};
    if (strict) {
        args.push_back("--strict");
    }
    return test::run_radcache(args);
}

// Silently accepted: --frames outside the scene's animation range rendered frames that hold the
// poses of its nearest end (or, without animation, the same picture each time) without a word.
// Warned now, naming the frames and what they show; --strict makes it an error, before any image.
TEST(HostileInput, FramesOutsideTheSceneRangeAreWarned) {
    const auto inside = test::scratch_dir("hostile_frames_inside");
    const test::CommandResult whole = render_frames("moving-sphere", "0:23", inside);
    EXPECT_EQ(whole.exit_code, 0) << whole.output;
    EXPECT_EQ(whole.output, "");
    EXPECT_EQ(files_in(inside), 24u);

    const auto past = test::scratch_dir("hostile_frames_past");
    const test::CommandResult both = render_frames("moving-sphere", "-2:25", past);
    EXPECT_EQ(both.exit_code, 0) << both.output;
    EXPECT_EQ(both.output,
              "radcache: warning: --frames -2:25 reaches outside the scene's frame range 0:23: "
              "frames -2 to -1 hold the poses of frame 0, frames 24 to 25 hold the poses of "
              "frame 23\n");
    EXPECT_EQ(files_in(past), 28u);

    const auto after = test::scratch_dir("hostile_frames_after");
    const test::CommandResult late = render_frames("moving-sphere", "30:31", after, true);
    EXPECT_EQ(late.exit_code, 1) << late.output;
    EXPECT_NE(late.output.find("error: --frames 30:31 reaches outside the scene's frame range "
                               "0:23: frames 30 to 31 hold the poses of frame 23 (a warning; "
                               "--strict makes it an error)"),
              std::string::npos)
        << late.output;
    EXPECT_EQ(files_in(after), 0u);

    const auto still = test::scratch_dir("hostile_frames_still");
    const test::CommandResult static_scene = render_frames("cornell-box", "0:1", still);
    EXPECT_EQ(static_scene.exit_code, 0) << static_scene.output;
    EXPECT_EQ(static_scene.output,
              "radcache: warning: --frames 0:1: the scene has no animation (its frame range is "
              "0:0): every frame is the same picture\n");
    const test::CommandResult strict_static = render_frames("cornell-box", "3:3", still, true);
    EXPECT_EQ(strict_static.exit_code, 1) << strict_static.output;
    EXPECT_NE(strict_static.output.find("--frames 3:3: the scene has no animation"),
              std::string::npos)
        << strict_static.output;
    EXPECT_FALSE(std::filesystem::exists(still / "f0003.png"));
}

}  // namespace
}  // namespace rc
