// The closed box [-1, 1]^3 the scenes written by the tests stand in: its walls as scene JSON,
// and the temporal tests' scenes in it.
#pragma once

#include <filesystem>
#include <string>

namespace rc::test {

// The material of each wall; no front wall where `front` is empty.
struct BoxWalls {
    std::string floor = "white";    // y = -1
    std::string ceiling = "white";  // y = 1
    std::string back = "white";     // z = 1
    std::string front;              // z = -1
    std::string right = "white";    // x = 1
    std::string left = "white";     // x = -1
};

// The walls as entries of a scene's "shapes" (rectangles facing into the box, in the order of
// BoxWalls' fields), separated by commas, with no comma before or after.
std::string box_walls_json(const BoxWalls& walls);

// The animation of a scene that does not move.
inline constexpr const char* kStillAnimation =
    R"({"frame_start": 0, "frame_end": 0, "tracks": []})";

// The temporal tests' scene: the closed box (the right wall red, the others white, a front wall
// too) seen from (0, 0, -0.95) looking down at (0, -0.5, 0) (fov 70, size x size pixels), with
// `shapes` after the walls (each entry after a comma), `emitters` and `animation` (JSON); with
// `satin_back`, its back wall glossy (Phong, exponent 8). Written to the scratch folder `name`;
// the scene file.
std::filesystem::path temporal_box_scene(const std::string& name, int size, bool satin_back,
                                         const std::string& shapes, const std::string& emitters,
                                         const std::string& animation);

}  // namespace rc::test
