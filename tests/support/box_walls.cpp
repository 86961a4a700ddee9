#include "box_walls.h"

#include <fstream>

#include "test_support.h"

namespace rc::test {
namespace {

// A unit rectangle of `material` placed by the JSON transforms `transform`.
std::string wall(const std::string& material, const std::string& transform) {
    return R"({"type": "rectangle", "material": ")" + material + R"(", "transform": [)" +
           transform + "]}";
}

}  // namespace

std::string box_walls_json(const BoxWalls& walls) {
    std::string json =
        wall(walls.floor,
             R"({"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"translate": [0, -1, 0]})") +
        ",\n" +
        wall(walls.ceiling,
             R"({"rotate": {"axis": [1, 0, 0], "angle": 90}}, {"translate": [0, 1, 0]})") +
        ",\n" +
        wall(walls.back,
             R"({"rotate": {"axis": [0, 1, 0], "angle": 180}}, {"translate": [0, 0, 1]})");
    if (!walls.front.empty()) {
        json += ",\n" + wall(walls.front, R"({"translate": [0, 0, -1]})");
    }
    return json + ",\n" +
           wall(walls.right,
                R"({"rotate": {"axis": [0, 1, 0], "angle": -90}}, {"translate": [1, 0, 0]})") +
           ",\n" +
           wall(walls.left,
                R"({"rotate": {"axis": [0, 1, 0], "angle": 90}}, {"translate": [-1, 0, 0]})");
}

std::filesystem::path temporal_box_scene(const std::string& name, int size, bool satin_back,
                                         const std::string& shapes, const std::string& emitters,
                                         const std::string& animation) {
    const auto dir = scratch_dir(name);
    BoxWalls walls;
    walls.front = "white";
    walls.right = "red";
    std::string materials = R"({"white": {"type": "diffuse", "reflectance": 0.6},
                      "red": {"type": "diffuse", "reflectance": [0.7, 0.15, 0.1]})";
    if (satin_back) {
        walls.back = "satin";
        materials += R"(,
                      "satin": {"type": "phong", "diffuse": 0.3, "specular": 0.4,
                                "exponent": 8})";
    }
    const std::string pixels = std::to_string(size);
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0, 0, -0.95], "look_at": [0, -0.5, 0], "up": [0, 1, 0],
                   "fov": 70, "resolution": [)"
                                      << pixels << ", " << pixels << R"(]},
        "materials": )" << materials << R"(},
        "shapes": [)" << box_walls_json(walls)
                                      << shapes << R"(],
        "emitters": [)" << emitters << R"(],
        "animation": )" << animation << R"(
    })";
    return dir / "scene.json";
}

}  // namespace rc::test
