// Wavefront OBJ meshes through tinyobjloader, validated first: every vertex must be finite and
// every face index must name an existing vertex, and the MTL values radcache reads must be finite
// and in range, else an error names the file and line. Polygons are triangulated in linear time.
#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "scene/scene_files.h"
#include "scene/triangle_mesh.h"

namespace rc {

// A material of the OBJ's MTL library, as read (mapped to radcache materials by the scene
// loader: Kd, Ks, Ns and map_Kd make the material, Ke an area light).
struct ObjMaterial {
    std::string name;
    glm::vec3 kd{0.0f};
    glm::vec3 ks{0.0f};
    float ns = 0.0f;
    glm::vec3 ke{0.0f};
    std::filesystem::path map_kd;  // empty: none
};

struct ObjData {
    // Positions and triangles (polygons fan-triangulated) of every object in the file. Normals and
    // uvs when every face has them (vertices are split where a position has several); the
    // material slot of each triangle indexes `materials` (-1: none given).
    TriangleMesh mesh;
    std::vector<ObjMaterial> materials;
    std::vector<std::string> warnings;
};

// Reads the OBJ file and its MTL libraries through `files`; Error naming the file and line for a
// bad vertex, face index or MTL value.
ObjData load_obj(const std::filesystem::path& path, const SceneFiles& files = disk_files());

}  // namespace rc
