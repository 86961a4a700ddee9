// Coincident copies of a shape's triangles: the Cornell box whose floor repeats its two triangles
// 100 000 times and whose light repeats its own once renders, with every method that traces
// photons or paths, bitwise the image of the box without the copies, and says what it dropped.
// Before, every photon ray tested all 100 000 copies (the grid methods ran for minutes: no BVH can
// split coincident triangles), and the light's copies doubled its area in light sampling.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glossy_scenes.h"
#include "image/image.h"
#include "image/image_io.h"
#include "test_support.h"

namespace rc {
namespace {

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The Cornell box with absolute mesh paths; with `copies`, the floor's faces repeated that many
// times and the light's once, in meshes of the scene's own folder.
std::filesystem::path cornell_box(const std::string& name, int copies) {
    const std::filesystem::path box = test::source_dir() / "scenes" / "cornell-box";
    const std::filesystem::path dir = test::scratch_dir("repeated_triangles_" + name);
    nlohmann::json scene =
        nlohmann::json::parse(read_text(box / "scene.json"), nullptr, true, true);
    for (nlohmann::json& shape : scene["shapes"]) {
        const std::string file = shape["file"].get<std::string>();
        shape["file"] = (box / file).string();
        const std::string shape_name = shape["name"].get<std::string>();
        if (copies > 0 && (shape_name == "floor" || shape_name == "light")) {
            std::string text = read_text(box / file);
            std::string repeated = text;
            const int times = shape_name == "floor" ? copies : 1;
            for (int i = 0; i < times; ++i) {
                repeated += "f 1 2 3\nf 1 3 4\n";
            }
            const std::filesystem::path copy = dir / (shape_name + ".obj");
            std::ofstream(copy) << repeated;
            shape["file"] = copy.string();
        }
    }
    const std::filesystem::path path = dir / "scene.json";
    std::ofstream(path) << scene.dump(1);
    return path;
}

struct Rendered {
    Image beauty;
    std::string output;
    nlohmann::json stats;
};

Rendered render(const std::filesystem::path& scene, const std::string& method) {
    const std::filesystem::path out = scene.parent_path() / (method + ".exr");
    const std::filesystem::path stats = scene.parent_path() / (method + ".json");
    const test::CommandResult result = test::run_radcache(
        {"render", scene.string(), "--method", method, "--width", "24", "--height", "24", "--spp",
         "2", "--seed", "5", "-o", out.string(), "--stats", stats.string()});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return {select_layers(read_image(out), {"beauty"}), result.output,
            nlohmann::json::parse(read_text(stats))};
}

TEST(RepeatedTriangles, CopiesRenderAsTheShapeWithoutThem) {
    const std::filesystem::path plain = cornell_box("plain", 0);
    const std::filesystem::path copied = cornell_box("copied", 100000);
    for (const std::string method : {"pt", "ivg", "decomposition"}) {
        const Rendered a = render(plain, method);
        const Rendered b = render(copied, method);
        EXPECT_TRUE(test::bitwise_equal(a.beauty, b.beauty))
            << method << ": the image differs from the box without copies";
        EXPECT_EQ(a.stats["dropped_repeated_triangles"], 0) << method;
        EXPECT_EQ(b.stats["dropped_repeated_triangles"], 200002) << method;
        EXPECT_NE(b.output.find("dropped 200002 triangles that repeat an earlier triangle of "
                                "their shape"),
                  std::string::npos)
            << b.output;
    }
}

}  // namespace
}  // namespace rc
