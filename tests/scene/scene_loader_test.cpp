// Scene and OBJ loading: what loads, what is dropped and counted, and a one-line error naming
// the file and the key or line for each kind of bad input.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

#include "error_of.h"
#include "image/image.h"
#include "image/image_io.h"
#include "scene/obj_loader.h"
#include "scratch_files.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

void expect_contains(const std::string& message, std::initializer_list<std::string> parts) {
    EXPECT_FALSE(message.empty()) << "no error";
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    for (const std::string& part : parts) {
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
}

const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjLoader, TriangulatesPolygonsAndResolvesNegativeIndices) {
    const auto dir = test::scratch_dir("obj_ok");
    const TriangleMesh mesh =
        load_obj(test::write_file(dir / "a.obj", std::string(kSquare) + "f 1 2 3 4\nf -4 -2 -1\n"))
            .mesh;
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.triangles.size(), 3u);
}

TEST(ObjLoader, RejectsNonFiniteVerticesWithFileAndLine) {
    const auto dir = test::scratch_dir("obj_nan");
    for (const std::string bad : {"nan", "inf", "-inf", "1e39", "NaN"}) {
        const auto file = test::write_file(
            dir / "bad.obj", "# comment\nv 0 0 0\nv 1 " + bad + " 0\nv 0 1 0\nf 1 2 3\n");
        expect_contains(test::error_of([&] { load_obj(file); }),
                        {"bad.obj:3:", "'" + bad + "'", "not finite"});
    }
}

TEST(ObjLoader, RejectsMalformedVertices) {
    const auto dir = test::scratch_dir("obj_malformed");
    const auto file = test::write_file(dir / "bad.obj", "v 0 0\n");
    expect_contains(test::error_of([&] { load_obj(file); }),
                    {"bad.obj:1:", "fewer than 3 coordinates"});
    const auto word = test::write_file(dir / "word.obj", "v 0 zero 0\n");
    expect_contains(test::error_of([&] { load_obj(word); }), {"word.obj:1:", "'zero'"});
}

TEST(ObjLoader, RejectsOutOfRangeFaceIndicesWithFileAndLine) {
    const auto dir = test::scratch_dir("obj_range");
    for (const std::string face : {"f 1 2 9", "f 0 1 2", "f -1 -2 -9", "f 1 2 x"}) {
        const auto file =
            test::write_file(dir / "bad.obj", std::string(kSquare) + "\n" + face + "\n");
        expect_contains(test::error_of([&] { load_obj(file); }), {"bad.obj:6:"});
    }
}

// Found by the obj fuzz target (tests/fuzz/regressions/obj/vertical_tab_vertex_line): a line
// "\vv ..." is a vertex to a C++ stream but not to tinyobjloader, so the text's face indices were
// checked against one more vertex than was parsed, and the face read past the vertices.
TEST(ObjLoader, FaceIndicesAreCheckedAgainstTheVerticesAsParsed) {
    const auto dir = test::scratch_dir("obj_vertical_tab");
    const auto file = test::write_file(dir / "bad.obj", "v 0 0 0\nv 1 0 0\n\vv 0 1 0\nf 1 2 3\n");
    expect_contains(test::error_of([&] { load_obj(file); }),
                    {"bad.obj", "vertex index 3 out of range", "2 vertices"});
}

TEST(ObjLoader, MissingFileIsNamed) {
    expect_contains(test::error_of([] { load_obj("/nonexistent/mesh.obj"); }),
                    {"/nonexistent/mesh.obj"});
}

std::string scene_with(const std::string& camera, const std::string& shapes) {
    return "{\n  // a comment\n  \"camera\": " + camera + ",\n  \"shapes\": " + shapes + "\n}\n";
}
const std::string kCamera =
    R"({"position": [0, 0, -5], "look_at": [0, 0, 0], "fov": 40, "resolution": [64, 48]})";

TEST(SceneLoader, LoadsShapesRelativeToTheSceneFileAndDropsDegenerateTriangles) {
    const auto dir = test::scratch_dir("scene_ok");
    std::filesystem::create_directories(dir / "meshes");
    // Triangle 2 repeats a vertex, triangle 3 is collinear: both have zero area.
    test::write_file(dir / "meshes/m.obj",
                     std::string(kSquare) + "v 2 0 0\nf 1 2 3\nf 1 1 2\nf 1 2 5\nf 1 3 4\n");
    const Scene scene = load_scene(test::write_file(
        dir / "scene.json", scene_with(kCamera, R"([{"type": "obj", "file": "meshes/m.obj"}])")));
    EXPECT_EQ(scene.mesh.triangle_count(), 2u);
    EXPECT_EQ(scene.dropped_degenerate, 2u);
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shapes[0].name, "m");
    EXPECT_EQ(scene.shapes[0].triangle_count, 2u);
    EXPECT_EQ(scene.camera.width, 64);
    EXPECT_EQ(scene.camera.height, 48);
    EXPECT_FLOAT_EQ(scene.camera.fov_degrees, 40.0f);
}

TEST(SceneLoader, DropsTrianglesThatRepeatAnEarlierOneOfTheirShape) {
    const auto dir = test::scratch_dir("scene_repeated");
    // 1 2 3 again, rotated (2 3 1) and as a copy with the same corners written again (5 6 7 =
    // 1 2 3): dropped. Reversed (3 2 1, the other side) and in another shape: kept.
    test::write_file(dir / "a.obj", std::string(kSquare) +
                                        "v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                        "f 1 2 3\nf 1 3 4\nf 2 3 1\nf 1 2 3\nf 5 6 7\nf 3 2 1\n");
    test::write_file(dir / "b.obj", std::string(kSquare) + "f 1 2 3\n");
    const Scene scene = load_scene(test::write_file(
        dir / "scene.json",
        scene_with(kCamera,
                   R"([{"type": "obj", "file": "a.obj"}, {"type": "obj", "file": "b.obj"}])")));
    EXPECT_EQ(scene.dropped_repeated, 3u);
    EXPECT_EQ(scene.dropped_degenerate, 0u);
    ASSERT_EQ(scene.shapes.size(), 2u);
    EXPECT_EQ(scene.shapes[0].triangle_count, 3u);
    EXPECT_EQ(scene.shapes[1].triangle_count, 1u);
    EXPECT_EQ(scene.mesh.triangle_count(), 4u);
}

TEST(SceneLoader, TheCornellBoxHasItsPublishedDimensions) {
    const Scene scene = test::load_cornell_box();
    EXPECT_EQ(scene.shapes.size(), 8u);
    EXPECT_EQ(scene.dropped_degenerate, 0u);
    glm::vec3 lower(1e9f), upper(-1e9f);
    for (const glm::vec3& p : scene.mesh.positions) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    EXPECT_EQ(lower, glm::vec3(0.0f, 0.0f, 0.0f));
    EXPECT_EQ(upper, glm::vec3(556.0f, 548.8f, 559.2f));
    EXPECT_EQ(scene.camera.position, glm::vec3(278.0f, 273.0f, -800.0f));
}

struct BadScene {
    std::string name;
    std::string text;
    std::vector<std::string> expected;
};

TEST(SceneLoader, BadScenesGiveOneLineErrorsNamingFileAndKey) {
    const auto dir = test::scratch_dir("scene_bad");
    test::write_file(dir / "ok.obj", std::string(kSquare) + "f 1 2 3\n");
    test::write_file(dir / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    // Environment maps: 2 x 1 (not square), all black, one texel infinite.
    for (const auto& [name, first] : {std::pair{"wide.exr", 1.0f},
                                      {"black.exr", 0.0f},
                                      {"infinite.exr", std::numeric_limits<float>::infinity()}}) {
        Image map(2, 1, 3);
        map.channel_names = {"R", "G", "B"};
        std::fill(map.pixels.begin(), map.pixels.end(), first == 0.0f ? 0.0f : 1.0f);
        map.pixels[0] = first;
        write_image(dir / name, map);
    }
    const std::string shape = R"([{"type": "obj", "file": "ok.obj"}])";
    const auto with_emitters = [&](const std::string& emitters) {
        return scene_with(kCamera, shape).replace(1, 0, "\"emitters\": " + emitters + ",");
    };
    const std::vector<BadScene> cases = {
        {"malformed", "{\n  \"camera\": {\n    \"fov\": 40,,\n", {"malformed JSON", "line 3"}},
        {"unknown_top",
         scene_with(kCamera, shape).replace(1, 0, "\"cameras\": {},"),
         {"cameras", "unknown key"}},
        {"unknown_shape",
         scene_with(kCamera, R"([{"type": "teapot"}])"),
         {"shapes[0].type", "teapot"}},
        {"missing_mesh",
         scene_with(kCamera, R"([{"type": "obj", "file": "nowhere.obj"}])"),
         {"shapes[0].file", "nowhere.obj"}},
        {"zero_resolution",
         scene_with(
             R"({"position": [0,0,-5], "look_at": [0,0,0], "fov": 40, "resolution": [0, 48]})",
             shape),
         {"camera.resolution", "[1, 65536]"}},
        {"bad_fov",
         scene_with(R"({"position": [0,0,-5], "look_at": [0,0,0], "fov": "wide"})", shape),
         {"camera.fov", "number"}},
        {"huge_fov",
         scene_with(R"({"position": [0,0,-5], "look_at": [0,0,0], "fov": 180})", shape),
         {"camera.fov"}},
        {"look_at_eye",
         scene_with(R"({"position": [1,2,3], "look_at": [1,2,3], "fov": 40})", shape),
         {"camera.look_at"}},
        {"up_parallel",
         scene_with(R"({"position": [0,0,0], "look_at": [0,1,0], "up": [0,1,0], "fov": 40})",
                    shape),
         {"camera.up"}},
        {"missing_camera", "{\"shapes\": " + shape + "}", {"camera", "missing"}},
        {"no_triangles", scene_with(kCamera, "[]"), {"no triangles"}},
        {"vector_size",
         scene_with(R"({"position": [0,0], "look_at": [0,0,0], "fov": 40})", shape),
         {"camera.position", "three numbers"}},
        {"unknown_material_type",
         scene_with(kCamera, shape).replace(1, 0, R"("materials": {"m": {"type": "plastic"}},)"),
         {"materials.m.type", "plastic"}},
        {"unknown_material_name",
         scene_with(kCamera, R"([{"type": "obj", "file": "ok.obj", "material": "gold"}])"),
         {"shapes[0].material", "gold"}},
        {"albedo_above_one",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("materials": {"m": {"type": "diffuse", "reflectance": [0.5, 1.2, 0.5]}},)"),
         {"materials.m.reflectance", "1.2"}},
        {"phong_albedo_above_one",
         scene_with(kCamera, shape)
             .replace(1, 0,
                      R"("materials": {"m": {"type": "phong", "diffuse": 0.6, "specular": 0.5}},)"),
         {"materials.m", "exceeds 1"}},
        {"negative_albedo",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("materials": {"m": {"type": "diffuse", "reflectance": -0.1}},)"),
         {"materials.m.reflectance"}},
        {"ward_alpha",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("materials": {"m": {"type": "ward", "alpha_x": 0}},)"),
         {"materials.m.alpha_x"}},
        {"negative_radiance",
         scene_with(kCamera, R"([{"type": "rectangle",
                                  "emitter": {"type": "area", "radiance": [1, -2, 1]}}])"),
         {"shapes[0].emitter.radiance", "-2"}},
        {"zero_area_emitter",
         scene_with(kCamera, R"([{"type": "obj", "file": "flat.obj",
                                  "emitter": {"type": "area", "radiance": 5}}])"),
         {"shapes[0]", "zero area"}},
        {"singular_transform",
         scene_with(kCamera, R"([{"type": "cube", "transform": [{"scale": [1, 0, 1]}]}])"),
         {"shapes[0].transform", "not invertible"}},
        {"bad_transform_step",
         scene_with(kCamera, R"([{"type": "cube", "transform": [{"shear": 2}]}])"),
         {"shapes[0].transform[0]", "shear"}},
        {"unknown_emitter",
         scene_with(kCamera, shape).replace(1, 0, R"("emitters": [{"type": "laser"}],)"),
         {"emitters[0].type", "laser"}},
        {"distant_zero_direction",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("emitters": [{"type": "distant", "direction": [0, 0, 0]}],)"),
         {"emitters[0].direction", "zero vector"}},
        {"distant_negative_irradiance",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("emitters": [{"type": "distant", "direction": [0, -1, 0], "irradiance": [1, -1, 1]}],)"),
         {"emitters[0].irradiance", "-1"}},
        {"distant_position",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("emitters": [{"type": "distant", "direction": [0, -1, 0], "position": [0, 1, 0]}],)"),
         {"emitters[0]", "position"}},
        {"envmap_missing",
         with_emitters(R"([{"type": "envmap", "filename": "nope.exr"}])"),
         {"emitters[0].filename", "nope.exr", "not found"}},
        {"envmap_mapping",
         with_emitters(R"([{"type": "envmap", "filename": "wide.exr", "mapping": "cube"}])"),
         {"emitters[0].mapping", "cube"}},
        {"envmap_not_square",
         with_emitters(R"([{"type": "envmap", "filename": "wide.exr", "mapping": "equal-area"}])"),
         {"emitters[0].filename", "wide.exr", "must be square"}},
        {"envmap_infinite",
         with_emitters(R"([{"type": "envmap", "filename": "infinite.exr"}])"),
         {"emitters[0].filename", "infinite.exr", "not finite"}},
        {"envmap_black",
         with_emitters(R"([{"type": "envmap", "filename": "black.exr"}])"),
         {"black.exr", "black everywhere"}},
        {"two_environments",
         with_emitters(R"([{"type": "constant"}, {"type": "envmap", "filename": "wide.exr"}])"),
         {"emitters[1].type", "at most one environment"}},
        {"ior_zero",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("materials": {"g": {"type": "dielectric", "ior": 0}},)"),
         {"materials.g.ior", "[1, 10]"}},
        {"ior_negative",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("materials": {"g": {"type": "thindielectric", "ior": -1.5}},)"),
         {"materials.g.ior", "[1, 10]"}},
        {"alpha_range",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("materials": {"g": {"type": "dielectric", "alpha": 1.5}},)"),
         {"materials.g.alpha", "[0, 1]"}},
        {"alpha_y_negative",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("materials": {"m": {"type": "conductor", "reflectance": 0.9, "alpha_y": -0.1}},)"),
         {"materials.m.alpha_y", "[0, 1]"}},
        {"conductor_without_k",
         scene_with(kCamera, shape)
             .replace(1, 0,
                      R"("materials": {"m": {"type": "conductor", "eta": [0.2, 0.9, 1.1]}},)"),
         {"materials.m", "needs \"eta\" and \"k\""}},
        {"conductor_both_forms",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("materials": {"m": {"type": "conductor", "reflectance": 0.9, "eta": 1, "k": 2}},)"),
         {"materials.m.reflectance", "not both"}},
        {"conductor_eta_zero",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("materials": {"m": {"type": "conductor", "eta": 0, "k": 2}},)"),
         {"materials.m.eta", "outside"}},
        {"transmitter_albedo",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("materials": {"m": {"type": "diffusetransmission", "reflectance": 0.6, "transmittance": 0.5}},)"),
         {"materials.m", "exceeds 1"}},
        {"thin_roughness",
         scene_with(kCamera, shape)
             .replace(1, 0, R"("materials": {"g": {"type": "thindielectric", "alpha": 0.2}},)"),
         {"materials.g", "alpha"}},
        {"missing_texture",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("materials": {"m": {"type": "diffuse", "reflectance": {"type": "bitmap", "filename": "wood.png"}}},)"),
         {"materials.m.reflectance.filename", "wood.png"}},
        {"unknown_render_key",
         scene_with(kCamera, shape).replace(1, 0, R"("render": {"samples": 4},)"),
         {"render", "samples"}},
        {"animation_target",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("animation": {"tracks": [{"target": "shape:nothing", "keyframes": [{"frame": 0}]}]},)"),
         {"animation.tracks[0].target", "nothing"}},
        {"animation_twice",
         scene_with(kCamera, shape)
             .replace(
                 1, 0,
                 R"("animation": {"tracks": [{"target": "camera", "keyframes": [{"frame": 0}]}, {"target": "camera", "keyframes": [{"frame": 1, "translate": [1, 0, 0]}]}]},)"),
         {"animation.tracks[1].target", "a second track for 'camera'"}},
    };
    for (const BadScene& bad : cases) {
        SCOPED_TRACE(bad.name);
        const auto file = test::write_file(dir / (bad.name + ".json"), bad.text);
        std::vector<std::string> expected = bad.expected;
        expected.push_back(bad.name + ".json");
        const std::string message = test::error_of([&] { load_scene(file); });
        EXPECT_FALSE(message.empty());
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        for (const std::string& part : expected) {
            EXPECT_NE(message.find(part), std::string::npos)
                << "'" << part << "' not in: " << message;
        }
    }
    expect_contains(test::error_of([&] { load_scene(dir / "absent.json"); }),
                    {"absent.json", "not found"});
}

TEST(SceneLoader, MtlMaterialsMapToDiffusePhongAndAreaLights) {
    const auto dir = test::scratch_dir("scene_mtl");
    test::write_file(dir / "m.mtl",
                     "newmtl matte\nKd 0.5 0.4 0.3\n"
                     "newmtl shiny\nKd 0.2 0.2 0.2\nKs 0.5 0.5 0.5\nNs 40\n"
                     "newmtl lamp\nKd 0 0 0\nKe 3 2 1\n");
    test::write_file(dir / "m.obj", "mtllib m.mtl\n" + std::string(kSquare) +
                                        "usemtl matte\nf 1 2 3\nusemtl shiny\nf 1 3 4\n"
                                        "v 0 0 1\nv 1 0 1\nv 0 1 1\nusemtl lamp\nf 5 6 7\n");
    const Scene scene = load_scene(test::write_file(
        dir / "scene.json", scene_with(kCamera, R"([{"type": "obj", "file": "m.obj"}])")));
    ASSERT_EQ(scene.mesh.triangle_count(), 3u);
    const auto material_of = [&](size_t t) { return scene.materials[scene.shading[t].material]; };
    EXPECT_EQ(material_of(0).kind, MaterialKind::kDiffuse);
    EXPECT_EQ(material_of(0).diffuse, glm::vec3(0.5f, 0.4f, 0.3f));
    EXPECT_EQ(material_of(1).kind, MaterialKind::kPhong);
    EXPECT_EQ(material_of(1).specular, glm::vec3(0.5f));
    EXPECT_EQ(material_of(1).exponent, 40.0f);
    ASSERT_EQ(scene.lights.lights.size(), 1u);
    EXPECT_EQ(scene.shading[2].light, 0);  // the Ke triangle is area light 0
    EXPECT_EQ(scene.shading[0].light, -1);
    EXPECT_EQ(scene.lights.lights[0].radiance.x, 3.0f);
    EXPECT_NEAR(scene.lights.lights[0].area, 0.5f, 1e-6f);  // its area
}

TEST(SceneLoader, BuiltInShapesAndTransforms) {
    const auto dir = test::scratch_dir("scene_builtin");
    const Scene scene = load_scene(test::write_file(dir / "scene.json", scene_with(kCamera, R"([
        {"type": "rectangle", "name": "r",
         "transform": [{"scale": [2, 3, 1]}, {"rotate": {"axis": [0, 0, 1], "angle": 90}},
                       {"translate": [10, 0, 0]}]},
        {"type": "cube", "name": "c", "flip_normals": true,
         "transform": [{"matrix": [1, 0, 0, 5,  0, 1, 0, 6,  0, 0, 1, 7,  0, 0, 0, 1]}]},
        {"type": "sphere", "name": "s", "center": [0, 0, 9], "radius": 2}
    ])")));
    ASSERT_EQ(scene.shapes.size(), 3u);
    // Rectangle corner (1, 1, 0): scaled to (2, 3), turned 90 degrees about z to (-3, 2), moved.
    const Shape& r = scene.shapes[0];
    const glm::vec3 corner = scene.mesh.positions[scene.mesh.triangles[r.first_triangle].z];
    EXPECT_NEAR(corner.x, 7.0f, 1e-5f);
    EXPECT_NEAR(corner.y, 2.0f, 1e-5f);
    // The cube is 12 triangles around (5, 6, 7), wound inwards.
    const Shape& c = scene.shapes[1];
    EXPECT_EQ(c.triangle_count, 12u);
    const glm::uvec3 t = scene.mesh.triangles[c.first_triangle];
    const glm::vec3 n = glm::cross(scene.mesh.positions[t.y] - scene.mesh.positions[t.x],
                                   scene.mesh.positions[t.z] - scene.mesh.positions[t.x]);
    const glm::vec3 to_centre = glm::vec3(5, 6, 7) - scene.mesh.positions[t.x];
    EXPECT_GT(glm::dot(n, to_centre), 0.0f);
    // Every sphere vertex is at the radius; it has smooth normals.
    const Shape& s = scene.shapes[2];
    for (size_t i = s.first_triangle; i < s.first_triangle + s.triangle_count; ++i) {
        const glm::vec3 p = scene.mesh.positions[scene.mesh.triangles[i].x];
        ASSERT_NEAR(glm::length(p - glm::vec3(0, 0, 9)), 2.0f, 1e-5f);
        ASSERT_GE(scene.shading[i].normal0, 0);
    }
}

TEST(SceneLoader, RenderDefaultsAndOverrides) {
    const auto dir = test::scratch_dir("scene_render");
    test::write_file(dir / "ok.obj", std::string(kSquare) + "f 1 2 3\n");
    const Scene scene = load_scene(test::write_file(
        dir / "scene.json",
        scene_with(kCamera, R"([{"type": "obj", "file": "ok.obj"}])")
            .replace(1, 0, R"("render": {"spp": 32, "max_depth": 5, "seed": 9},)")));
    RenderSettings settings = scene.render;
    EXPECT_EQ(settings.spp, 32);
    EXPECT_EQ(settings.max_depth, 5);
    settings.apply_override("spp=128");
    settings.apply_override("method=normals");
    settings.apply_override("exposure=-1.5");
    EXPECT_EQ(settings.spp, 128);
    EXPECT_EQ(settings.method, "normals");
    EXPECT_EQ(settings.exposure, -1.5f);
    EXPECT_EQ(settings.seed, 9u);
    for (const char* bad : {"spp", "spp=0", "spp=many", "depth=3", "=4", "max_depth=-1"}) {
        RenderSettings copy = settings;
        EXPECT_THROW(copy.apply_override(bad), Error) << bad;
    }
}

TEST(SceneLoader, BadSceneThroughTheCommandLineExitsNonZeroWithoutOutput) {
    const auto dir = test::scratch_dir("scene_bad_cli");
    test::write_file(dir / "bad.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    test::write_file(dir / "scene.json",
                     scene_with(kCamera, R"([{"type": "obj", "file": "bad.obj"}])"));
    const auto output = dir / "out.png";
    const test::CommandResult result =
        test::run_radcache({"render", (dir / "scene.json").string(), "-o", output.string()});
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("bad.obj:2:"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(output));
}

}  // namespace
}  // namespace rc
