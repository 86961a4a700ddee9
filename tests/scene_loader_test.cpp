// Scene and OBJ loading: what loads, what is dropped and counted, and a one-line error naming
// the file and the key or line for each kind of bad input.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <glm/common.hpp>

#include "scene/obj_loader.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

std::filesystem::path write(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

// The Error message of `load`, or "" when it does not throw.
template <class Load>
std::string error_of(const Load& load) {
    try {
        load();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

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
        load_obj(write(dir / "a.obj", std::string(kSquare) + "f 1 2 3 4\nf -4 -2 -1\n")).mesh;
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.triangles.size(), 3u);
}

TEST(ObjLoader, RejectsNonFiniteVerticesWithFileAndLine) {
    const auto dir = test::scratch_dir("obj_nan");
    for (const std::string& bad : {"nan", "inf", "-inf", "1e39", "NaN"}) {
        const auto file =
            write(dir / "bad.obj", "# comment\nv 0 0 0\nv 1 " + bad + " 0\nv 0 1 0\nf 1 2 3\n");
        expect_contains(error_of([&] { load_obj(file); }),
                        {"bad.obj:3:", "'" + bad + "'", "not finite"});
    }
}

TEST(ObjLoader, RejectsMalformedVertices) {
    const auto dir = test::scratch_dir("obj_malformed");
    const auto file = write(dir / "bad.obj", "v 0 0\n");
    expect_contains(error_of([&] { load_obj(file); }), {"bad.obj:1:", "fewer than 3 coordinates"});
    const auto word = write(dir / "word.obj", "v 0 zero 0\n");
    expect_contains(error_of([&] { load_obj(word); }), {"word.obj:1:", "'zero'"});
}

TEST(ObjLoader, RejectsOutOfRangeFaceIndicesWithFileAndLine) {
    const auto dir = test::scratch_dir("obj_range");
    for (const std::string& face : {"f 1 2 9", "f 0 1 2", "f -1 -2 -9", "f 1 2 x"}) {
        const auto file = write(dir / "bad.obj", std::string(kSquare) + "\n" + face + "\n");
        expect_contains(error_of([&] { load_obj(file); }), {"bad.obj:6:"});
    }
}

TEST(ObjLoader, MissingFileIsNamed) {
    expect_contains(error_of([] { load_obj("/nonexistent/mesh.obj"); }), {"/nonexistent/mesh.obj"});
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
    write(dir / "meshes/m.obj",
          std::string(kSquare) + "v 2 0 0\nf 1 2 3\nf 1 1 2\nf 1 2 5\nf 1 3 4\n");
    const Scene scene = load_scene(write(
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
    write(dir / "ok.obj", std::string(kSquare) + "f 1 2 3\n");
    const std::string shape = R"([{"type": "obj", "file": "ok.obj"}])";
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
         {"camera.resolution", "positive"}},
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
    };
    for (const BadScene& bad : cases) {
        SCOPED_TRACE(bad.name);
        const auto file = write(dir / (bad.name + ".json"), bad.text);
        std::vector<std::string> expected = bad.expected;
        expected.push_back(bad.name + ".json");
        const std::string message = error_of([&] { load_scene(file); });
        EXPECT_FALSE(message.empty());
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        for (const std::string& part : expected) {
            EXPECT_NE(message.find(part), std::string::npos)
                << "'" << part << "' not in: " << message;
        }
    }
    expect_contains(error_of([&] { load_scene(dir / "absent.json"); }),
                    {"absent.json", "not found"});
}

TEST(SceneLoader, BadSceneThroughTheCommandLineExitsNonZeroWithoutOutput) {
    const auto dir = test::scratch_dir("scene_bad_cli");
    write(dir / "bad.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    write(dir / "scene.json", scene_with(kCamera, R"([{"type": "obj", "file": "bad.obj"}])"));
    const auto output = dir / "out.png";
    const test::CommandResult result =
        test::run_radcache({"render", (dir / "scene.json").string(), "-o", output.string()});
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("bad.obj:2:"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(output));
}

}  // namespace
}  // namespace rc
