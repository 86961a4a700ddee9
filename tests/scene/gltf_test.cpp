// glTF 2.0 import (scene/gltf_loader.h) and `radcache convert`: the Cornell box as glTF renders
// the image of scenes/cornell-box bitwise; an asymmetric hierarchy lands where its transforms put
// it, with its cameras, materials and lights mapped as docs/scene-format.md says; a converted
// scene renders bitwise as its glTF; malformed files are refused with one line naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "cli_render.h"
#include "glossy_scenes.h"  // test::bitwise_equal
#include "scene/gltf_materials.h"
#include "scene/json_parse.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

std::filesystem::path data(const std::string& name) {
    return test::source_dir() / "tests/data/gltf" / name;
}

// test::render_scene_file at 32 x 32, then `extra`.
Image render(const std::filesystem::path& scene, const std::filesystem::path& out,
             std::vector<std::string> extra = {}) {
    extra.insert(extra.begin(), {"--width", "32", "--height", "32"});
    return test::render_scene_file(scene, out, extra);
}

TEST(Gltf, CornellBoxRendersTheJsonScenesImageBitwise) {
    const auto dir = test::scratch_dir("gltf_cornell");
    // Square (render's size): the JSON's fov spans x, the glTF camera's yfov spans y.
    const Image json = render(test::source_dir() / "scenes/cornell-box/scene.json", dir / "j.exr");
    const Image gltf = render(data("cornell-box.gltf"), dir / "g.exr");
    EXPECT_TRUE(test::bitwise_equal(json, gltf));
}

// The same model as a .glb (binary container; the fuzz target's seed, made from the seed
// hierarchy.gltf beside it) renders the same image.
TEST(Gltf, BinaryGlbRendersAsItsGltf) {
    const auto dir = test::scratch_dir("gltf_glb");
    const auto seeds = test::source_dir() / "tests/fuzz/seeds/gltf";
    const Image glb = render(seeds / "binary.glb", dir / "b.exr");
    EXPECT_TRUE(test::bitwise_equal(glb, render(seeds / "hierarchy.gltf", dir / "h.exr")));
}

void expect_near(glm::vec3 a, glm::vec3 b, const std::string& what) {
    EXPECT_LT(glm::length(a - b), 1e-5f)
        << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") against (" << b.x << ", " << b.y
        << ", " << b.z << ")";
}

const Shape& shape_named(const Scene& scene, const std::string& prefix) {
    for (const Shape& shape : scene.shapes) {
        if (shape.name.rfind(prefix, 0) == 0) {
            return shape;
        }
    }
    ADD_FAILURE() << "no shape " << prefix;
    return scene.shapes.front();
}

// The values below are worked out by hand from tools/make_gltf_test_scenes.py's hierarchy().
TEST(Gltf, HierarchyTransformsCamerasMaterialsAndLights) {
    const Scene scene = load_scene(data("hierarchy.gltf"));
    // The lamp: parent translate (1, 2, 3) and 90 degrees about z, child scale (0.5, 0.25, 1):
    // object corner (x, y, 0) lands at (1 - 0.25 y, 2 + 0.5 x, 3).
    const Shape& lamp = shape_named(scene, "lamp");
    for (const glm::vec3& p : lamp.mesh.positions) {
        const glm::vec3 world = glm::vec3(lamp.transform * glm::vec4(p, 1.0f));
        expect_near(world, glm::vec3(1.0f - 0.25f * p.y, 2.0f + 0.5f * p.x, 3.0f), "lamp");
    }
    ASSERT_EQ(lamp.emission.size(), 1u);
    expect_near(lamp.emission[0], glm::vec3(1.0f, 0.5f, 0.25f), "lamp emission");
    // The plate's matrix: scale 2, translate (-2, 0, 1).
    const Shape& plate = shape_named(scene, "plate");
    expect_near(glm::vec3(plate.transform * glm::vec4(1, 1, 0, 1)), glm::vec3(0, 2, 1), "plate");
    const Material& gold = scene.materials[plate.materials[0]];
    // A plain metal: the conductor reflecting the base colour at normal incidence (eta 1,
    // k = 2 sqrt(r / (1 - r))), alpha = roughness^2.
    EXPECT_EQ(gold.kind, MaterialKind::kConductor);
    expect_near(gold.eta, glm::vec3(1.0f), "metal eta");
    const glm::vec3 r(0.9f, 0.6f, 0.2f);
    expect_near(gold.k, 2.0f * glm::sqrt(r / (1.0f - r)), "metal k");
    expect_near(gold.diffuse, glm::vec3(0.0f), "metal diffuse");
    EXPECT_NEAR(gold.alpha_x, 0.09f, 1e-6f);
    // KHR_materials_transmission: thin-walled glass without KHR_materials_volume, solid glass of
    // KHR_materials_ior's index and alpha = roughness^2 with it.
    const Material& window = scene.materials[shape_named(scene, "window").materials[0]];
    EXPECT_EQ(window.kind, MaterialKind::kThinDielectric);
    EXPECT_FLOAT_EQ(window.ior, 1.5f);
    const Material& lens = scene.materials[shape_named(scene, "lens").materials[0]];
    EXPECT_EQ(lens.kind, MaterialKind::kDielectric);
    EXPECT_FLOAT_EQ(lens.ior, 1.33f);
    EXPECT_NEAR(lens.alpha_x, 0.04f, 1e-6f);
    const Material& floor = scene.materials[shape_named(scene, "ground").materials[0]];
    EXPECT_EQ(floor.kind, MaterialKind::kDiffuse);
    expect_near(floor.diffuse, glm::vec3(0.8f), "rough dielectric");
    const Material& checker = scene.materials[shape_named(scene, "picture").materials[0]];
    ASSERT_GE(checker.diffuse_texture, 0);
    EXPECT_EQ(scene.textures[checker.diffuse_texture].width, 2);
    // glTF's uv (0, 0) is the image's top-left, ours its bottom-left.
    const Shape& picture = shape_named(scene, "picture");
    ASSERT_EQ(picture.mesh.uvs.size(), 4u);
    EXPECT_EQ(picture.mesh.uvs[0], glm::vec2(0.0f, 0.0f));
    EXPECT_EQ(picture.mesh.uvs[2], glm::vec2(1.0f, 1.0f));
    // The first camera: at (0, 1, 10) looking down -z, vertical fov 0.8 rad, aspect 1.5.
    expect_near(scene.base_camera.position, glm::vec3(0, 1, 10), "camera");
    expect_near(scene.base_camera.look_at, glm::vec3(0, 1, 9), "camera look_at");
    expect_near(scene.base_camera.up, glm::vec3(0, 1, 0), "camera up");
    EXPECT_EQ(scene.base_camera.fov_axis, FovAxis::kY);
    EXPECT_NEAR(scene.base_camera.fov_degrees, 0.8 * 180.0 / M_PI, 1e-4);
    EXPECT_EQ(scene.base_camera.width, 768);
    EXPECT_EQ(scene.base_camera.height, 512);
    // --camera side: at (10, 1, 0), turned 90 degrees about y: looking down -x.
    const Scene side = load_scene(data("hierarchy.gltf"), disk_files(), "side");
    expect_near(side.base_camera.look_at, glm::vec3(9, 1, 0), "side camera");
    EXPECT_THROW(load_scene(data("hierarchy.gltf"), disk_files(), "nowhere"), Error);
    // Lights: a point light of colour (1, 0.8, 0.6) x 5, a spot at (0, 4, 0) pointing down, a
    // directional light of colour (1, 1, 0.5) x 0.5 lux travelling along -x.
    ASSERT_EQ(scene.emitters.size(), 3u);
    EXPECT_EQ(scene.emitters[0].kind, EmitterKind::kPoint);
    expect_near(scene.emitters[0].position, glm::vec3(0, 3, 2), "point light");
    expect_near(scene.emitters[0].intensity, glm::vec3(5, 4, 3), "point intensity");
    EXPECT_EQ(scene.emitters[1].kind, EmitterKind::kSpot);
    expect_near(scene.emitters[1].look_at, glm::vec3(0, 3, 0), "spot axis");
    EXPECT_NEAR(scene.emitters[1].cutoff_angle, 0.5 * 180.0 / M_PI, 1e-4);
    EXPECT_NEAR(scene.emitters[1].beam_width, 0.2 * 180.0 / M_PI, 1e-4);
    EXPECT_EQ(scene.emitters[2].kind, EmitterKind::kDistant);
    expect_near(scene.emitters[2].direction, glm::vec3(-1, 0, 0), "sun direction");
    expect_near(scene.emitters[2].irradiance, glm::vec3(0.5f, 0.5f, 0.25f), "sun irradiance");
}

// The lamp (upper right of the image seen from the front camera: x in [0.75, 1.25], y in
// [1.5, 2.5]) is brightest on the right half and upper half: no mirroring.
TEST(Gltf, ImageIsNotMirrored) {
    const auto dir = test::scratch_dir("gltf_mirror");
    const Image image = render(data("hierarchy.gltf"), dir / "h.exr", {"-D", "max_depth=0"});
    double left = 0, right = 0, top = 0, bottom = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const double v = image.at(x, y, 0);
            (x < image.width / 2 ? left : right) += v;
            (y < image.height / 2 ? top : bottom) += v;
        }
    }
    EXPECT_GT(right, 2 * left);
    EXPECT_GT(top, 2 * bottom);
}

TEST(Gltf, ConvertedSceneRendersBitwiseAsTheGltf) {
    const auto dir = test::scratch_dir("gltf_convert");
    for (const std::string name : {"cornell-box", "hierarchy"}) {
        const test::CommandResult result = test::run_radcache(
            {"convert", data(name + ".gltf").string(), (dir / (name + ".json")).string(), "-q"});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        const Image gltf = render(data(name + ".gltf"), dir / (name + "-g.exr"));
        const Image json = render(dir / (name + ".json"), dir / (name + "-j.exr"));
        EXPECT_TRUE(test::bitwise_equal(gltf, json)) << name;
    }
}

// Malformed files: one line naming the file, exit status 1, no image; well-formed files asking
// for what radcache does not do (a required extension, sparse accessors, an orthographic camera):
// the same with exit status 2.
TEST(Gltf, MalformedFilesAreRefusedCleanly) {
    const auto dir = test::scratch_dir("gltf_malformed");
    const std::string good = read_file(data("hierarchy.gltf"));
    nlohmann::json model = nlohmann::json::parse(good);
    struct Case {
        std::string name;
        std::string text;
        std::string expected;
        int exit_code = 1;
    };
    std::vector<Case> cases;
    cases.push_back({"truncated", good.substr(0, good.size() / 2), "truncated.gltf"});
    nlohmann::json m = model;
    m["accessors"][0]["count"] = "many";
    cases.push_back({"wrong_type", m.dump(), "wrong_type.gltf"});
    m = model;
    m["accessors"][0]["count"] = 100000;
    cases.push_back({"past_buffer", m.dump(), "elements (to byte"});
    // Each index error names its own cause: the view past its buffer (not the accessor), the
    // node that lists a missing child (not the child alone).
    m = model;
    m["bufferViews"][1]["byteOffset"] = 1 << 20;
    cases.push_back({"view_past_buffer", m.dump(), "buffer view 1 (bytes 1048576 to"});
    m = model;
    m["nodes"][1]["children"] = {77};
    cases.push_back({"missing_child", m.dump(), "node 1 lists node 77, which does not exist"});
    m = model;
    m["meshes"][0]["primitives"][0]["indices"] = 0;  // the positions as indices: wrong type
    cases.push_back({"bad_indices", m.dump(), "indices"});
    m = model;
    m["nodes"][1]["mesh"] = 99;
    cases.push_back({"missing_mesh", m.dump(), "mesh 99 does not exist"});
    m = model;
    m["buffers"][0]["uri"] = "missing.bin";
    cases.push_back({"missing_buffer", m.dump(), "missing_buffer.gltf"});
    // The lens (material 5): an index below 1, and a transmission factor outside [0, 1].
    m = model;
    m["materials"][5]["extensions"]["KHR_materials_ior"]["ior"] = 0.5;
    cases.push_back({"ior_below_one", m.dump(), "ior must be a number in [1, 10]"});
    m = model;
    m["materials"][5]["extensions"]["KHR_materials_transmission"]["transmissionFactor"] = 1.5;
    cases.push_back({"transmission_range", m.dump(), "transmissionFactor"});
    m = model;
    m["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    cases.push_back({"draco", m.dump(), "KHR_draco_mesh_compression", 2});
    m = model;
    m["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
                                   {"values", {{"bufferView", 1}}}};
    cases.push_back({"sparse", m.dump(), "sparse accessors are not supported", 2});
    m = model;
    m["cameras"][0] = {
        {"type", "orthographic"},
        {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}};
    cases.push_back({"orthographic", m.dump(), "perspective cameras only", 2});
    m = model;
    m["nodes"][1]["children"] = {1};
    cases.push_back({"cycle", m.dump(), "cycle"});
    m = model;
    m["accessors"][1]["bufferView"] = 1;  // the positions' float bits as indices
    cases.push_back({"index_range", m.dump(), "out of range"});
    // A light index that is no light: negative, past the end, not whole, beyond int, a string.
    const std::vector<std::pair<std::string, nlohmann::json>> light_indices = {
        {"light_negative", -1},
        {"light_past_end", 3},
        {"light_fraction", 0.5},
        {"light_huge", 1e20},
        {"light_string", "0"}};
    for (const auto& [name, index] : light_indices) {
        m = model;
        for (auto& node : m["nodes"]) {
            if (node.contains("extensions")) {
                node["extensions"]["KHR_lights_punctual"]["light"] = index;
            }
        }
        cases.push_back({name, m.dump(), "names no existing light"});
    }
    // What tinygltf reads silently wrong: a key given twice (the last would win), arrays of the
    // wrong length (replaced by defaults), a negative offset (read as 0), a matrix beside TRS
    // (the translation dropped), integer positions without KHR_mesh_quantization (read as
    // integers), an aspect ratio past the image limit (clamped to 65 536 pixels).
    std::string twice = model.dump();
    twice.insert(1, R"("asset": {"version": "2.0"}, )");
    cases.push_back({"key_twice", twice, "asset: key given twice in one object"});
    m = model;
    m["materials"][1]["pbrMetallicRoughness"]["baseColorFactor"] = {0.9, 0.6, 0.2};
    cases.push_back({"base_color_3", m.dump(),
                     "materials[1].pbrMetallicRoughness.baseColorFactor: [0.9,0.6,0.2] is not 4"});
    m = model;
    m["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1, 0.8};
    cases.push_back({"light_color_2", m.dump(),
                     "extensions.KHR_lights_punctual.lights[0].color: [1,0.8] is not 3 numbers"});
    m = model;
    m["accessors"][0]["byteOffset"] = -12;
    cases.push_back({"negative_offset", m.dump(), "accessors[0].byteOffset: -12 is negative"});
    m = model;
    m["nodes"][2]["translation"] = {5, 0, 0};
    cases.push_back({"matrix_and_trs", m.dump(), "nodes[2]: has both a matrix and a translation"});
    m = model;
    m["accessors"][0]["componentType"] = 5121;
    cases.push_back({"byte_positions", m.dump(),
                     "meshes[0].primitives[0].attributes.POSITION: accessor 0 has componentType "
                     "5121, not float"});
    m = model;
    m["cameras"][0]["perspective"]["aspectRatio"] = 1000.0;
    cases.push_back({"wide_aspect", m.dump(), "camera aspectRatio 1000.0 makes a 512-row image"});
    // A base colour texture whose image file is missing: the file named, not "no data".
    m = model;
    m["images"] = {{{"uri", "no-such-texture.png"}}};
    m["textures"] = {{{"source", 0}}};
    m["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    cases.push_back({"missing_texture", m.dump(), "image 0 'no-such-texture.png': file not found"});
    // Nested 20 000 deep in `extras` (30 KB): refused before tinygltf's recursive conversion of
    // `extras` would overflow the stack; brackets inside strings do not count.
    m = model;
    m["extras"] = {{"note", std::string(300, '[')}};
    std::string deep = m.dump();
    deep.insert(deep.size() - 1, ",\"more\":" + std::string(20000, '[') + std::string(20000, ']'));
    cases.push_back({"deep_extras", deep, "nested deeper than 64 levels"});
    for (const Case& c : cases) {
        const auto file = dir / (c.name + ".gltf");
        write_file_atomically(file, c.text);
        const test::CommandResult result = test::run_radcache(
            {"render", file.string(), "-o", (dir / "out.png").string(), "--spp", "1"});
        EXPECT_EQ(result.exit_code, c.exit_code) << c.name << ": " << result.output;
        EXPECT_NE(result.output.find("radcache: error: "), std::string::npos) << result.output;
        EXPECT_NE(result.output.find(c.expected), std::string::npos)
            << c.name << ": " << result.output;
        EXPECT_NE(result.output.find(file.filename().string()), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << c.name;
        std::filesystem::remove(dir / "out.png");
    }
    // The same in a .glb's JSON chunk.
    std::string chunk = deep + std::string((4 - deep.size() % 4) % 4, ' ');
    const auto word = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const std::string glb = "glTF" + word(2) + word(static_cast<uint32_t>(20 + chunk.size())) +
                            word(static_cast<uint32_t>(chunk.size())) + "JSON" + chunk;
    write_file_atomically(dir / "deep.glb", glb);
    const test::CommandResult deep_glb = test::run_radcache(
        {"render", (dir / "deep.glb").string(), "-o", (dir / "out.png").string(), "--spp", "1"});
    EXPECT_EQ(deep_glb.exit_code, 1) << deep_glb.output;
    EXPECT_NE(deep_glb.output.find("deep.glb: JSON nested deeper than 64 levels"),
              std::string::npos)
        << deep_glb.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    // Brackets inside strings (an escaped quote among them) are no nesting.
    EXPECT_EQ(json_nesting_depth("{\"a\": \"[[[[\\\"[[\", \"b\": [[1], {\"c\": []}]}"), 4);
    const test::CommandResult json_camera = test::run_radcache(
        {"render", (test::source_dir() / "scenes/cornell-box/scene.json").string(), "-o",
         (dir / "out.png").string(), "--camera", "main"});
    EXPECT_EQ(json_camera.exit_code, 2) << json_camera.output;
    // convert: a glTF in, a .json out, or exit status 2; a malformed glTF writes nothing.
    const auto convert = [&](const std::string& in, const std::string& out) {
        return test::run_radcache({"convert", in, (dir / out).string(), "-q"});
    };
    EXPECT_EQ(convert((test::source_dir() / "scenes/cornell-box/scene.json").string(), "c.json")
                  .exit_code,
              2);
    EXPECT_EQ(convert(data("hierarchy.gltf").string(), "c.txt").exit_code, 2);
    EXPECT_EQ(convert((dir / "truncated.gltf").string(), "c.json").exit_code, 1);
    EXPECT_FALSE(std::filesystem::exists(dir / "c.json"));
    EXPECT_FALSE(std::filesystem::exists(dir / "c.txt"));
}

// An unsupported feature is one warning (and an error under --strict).
TEST(Gltf, UnsupportedFeaturesWarnOnce) {
    const auto dir = test::scratch_dir("gltf_unsupported");
    nlohmann::json m = nlohmann::json::parse(read_file(data("hierarchy.gltf")));
    m["extensions"]["KHR_lights_punctual"]["lights"].push_back(
        {{"type", "sphere"}, {"intensity", 3.0}});  // a type KHR_lights_punctual does not define
    const int sphere =
        static_cast<int>(m["extensions"]["KHR_lights_punctual"]["lights"].size()) - 1;
    m["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", sphere}}}}}});
    m["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", sphere}}}}}});
    m["scenes"][0]["nodes"].push_back(m["nodes"].size() - 2);
    m["scenes"][0]["nodes"].push_back(m["nodes"].size() - 1);
    write_file_atomically(dir / "sun.gltf", m.dump());
    const test::CommandResult result =
        test::run_radcache({"render", (dir / "sun.gltf").string(), "-o", (dir / "out.png").string(),
                            "--spp", "1", "--width", "8", "--height", "8"});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    const std::string line = "glTF light type 'sphere' not supported";
    const size_t first = result.output.find(line);
    EXPECT_NE(first, std::string::npos) << result.output;
    EXPECT_EQ(result.output.find(line, first + 1), std::string::npos) << result.output;
    const test::CommandResult strict =
        test::run_radcache({"render", (dir / "sun.gltf").string(), "-o",
                            (dir / "strict.png").string(), "--spp", "1", "--strict"});
    EXPECT_NE(strict.exit_code, 0);
    EXPECT_FALSE(std::filesystem::exists(dir / "strict.png"));
}

TEST(Gltf, PhongExponentFollowsRoughness) {
    EXPECT_FLOAT_EQ(gltf_phong_exponent(1.0f), 0.0f);
    EXPECT_NEAR(gltf_phong_exponent(0.5f), 2.0f / std::pow(0.25f, 2.0f) - 2.0f, 1e-3);
    EXPECT_FLOAT_EQ(gltf_phong_exponent(0.0f), 1e6f);
}

}  // namespace
}  // namespace rc
