#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>

#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

// tinyobjloader reads "nan" and "inf" as 0 and does not report line numbers, so vertex and face
// lines are checked here before it parses the file.
void validate_obj_text(const std::string& text, const std::string& file) {
    long long vertex_total = 0;
    {
        std::istringstream lines(text);
        std::string line;
        while (std::getline(lines, line)) {
            std::istringstream tokens(line);
            std::string keyword;
            if (tokens >> keyword && keyword == "v") {
                ++vertex_total;
            }
        }
    }
    std::istringstream lines(text);
    std::string line;
    long long vertices_so_far = 0;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        const std::string where = file + ":" + std::to_string(number) + ": ";
        const size_t comment = line.find('#');
        std::istringstream tokens(line.substr(0, comment));
        std::string keyword;
        if (!(tokens >> keyword)) {
            continue;
        }
        if (keyword == "v" || keyword == "vn" || keyword == "vt") {
            if (keyword == "v") {
                ++vertices_so_far;
            }
            const int needed = keyword == "vt" ? 2 : 3;
            const char* what = keyword == "v"    ? "vertex"
                               : keyword == "vn" ? "normal"
                                                 : "texture coordinate";
            for (int axis = 0; axis < needed; ++axis) {
                std::string token;
                if (!(tokens >> token)) {
                    throw Error(where + what + " has fewer than " + std::to_string(needed) +
                                " coordinates");
                }
                char* end = nullptr;
                const double value = std::strtod(token.c_str(), &end);
                if (end == token.c_str() || *end != '\0') {
                    throw Error(where + what + " coordinate '" + token + "' is not a number");
                }
                if (!std::isfinite(value) || !std::isfinite(static_cast<float>(value))) {
                    throw Error(where + what + " coordinate '" + token + "' is not finite");
                }
            }
        } else if (keyword == "f") {
            std::string corner;
            int corners = 0;
            while (tokens >> corner) {
                ++corners;
                const std::string index_text = corner.substr(0, corner.find('/'));
                char* end = nullptr;
                const long long index = std::strtoll(index_text.c_str(), &end, 10);
                if (index_text.empty() || *end != '\0') {
                    throw Error(where + "face index '" + corner + "' is not an integer");
                }
                const long long resolved = index < 0 ? vertices_so_far + index + 1 : index;
                if (index == 0 || resolved < 1 || resolved > vertex_total) {
                    throw Error(where + "face index " + std::to_string(index) +
                                " is out of range (the file has " + std::to_string(vertex_total) +
                                " vertices)");
                }
            }
            if (corners < 3) {
                throw Error(where + "face has fewer than three vertices");
            }
        }
    }
}

}  // namespace

ObjData load_obj(const std::filesystem::path& path) {
    const std::string file = path.string();
    const std::string text = read_file(path);
    validate_obj_text(text, file);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning;
    std::string error;
    std::istringstream stream(text);
    std::string directory = path.parent_path().string();
    tinyobj::MaterialFileReader material_reader(directory.empty() ? "./" : directory + "/");
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, &material_reader,
                          /*triangulate=*/true,
                          /*default_vcols_fallback=*/false)) {
        throw Error(file + ": cannot parse OBJ: " + error);
    }
    ObjData data;
    if (!warning.empty()) {
        std::istringstream lines(warning);
        for (std::string line; std::getline(lines, line);) {
            if (!line.empty()) {
                data.warnings.push_back(file + ": " + line);
            }
        }
    }
    for (const tinyobj::material_t& m : materials) {
        ObjMaterial material;
        material.name = m.name;
        material.kd = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
        material.ks = {m.specular[0], m.specular[1], m.specular[2]};
        material.ns = m.shininess;
        material.ke = {m.emission[0], m.emission[1], m.emission[2]};
        if (!m.diffuse_texname.empty()) {
            material.map_kd = path.parent_path() / m.diffuse_texname;
        }
        data.materials.push_back(material);
    }

    // Every face corner (v, vt, vn) becomes a vertex, shared between corners with the same triple.
    bool all_normals = true;
    bool all_uvs = true;
    for (const tinyobj::shape_t& shape : shapes) {
        for (const tinyobj::index_t& index : shape.mesh.indices) {
            all_normals = all_normals && index.normal_index >= 0;
            all_uvs = all_uvs && index.texcoord_index >= 0;
        }
    }
    TriangleMesh& mesh = data.mesh;
    std::map<std::array<int, 3>, unsigned> vertex_of;
    auto vertex = [&](const tinyobj::index_t& index) {
        const std::array<int, 3> key = {index.vertex_index, all_uvs ? index.texcoord_index : -1,
                                        all_normals ? index.normal_index : -1};
        const auto found = vertex_of.find(key);
        if (found != vertex_of.end()) {
            return found->second;
        }
        if (index.vertex_index < 0 ||
            static_cast<size_t>(index.vertex_index) * 3 + 2 >= attrib.vertices.size()) {
            throw Error(file + ": vertex index " + std::to_string(index.vertex_index) +
                        " out of range");
        }
        const size_t v = static_cast<size_t>(index.vertex_index) * 3;
        mesh.positions.emplace_back(attrib.vertices[v], attrib.vertices[v + 1],
                                    attrib.vertices[v + 2]);
        if (all_normals) {
            const size_t n = static_cast<size_t>(index.normal_index) * 3;
            if (n + 2 >= attrib.normals.size()) {
                throw Error(file + ": normal index " + std::to_string(index.normal_index) +
                            " out of range");
            }
            mesh.normals.emplace_back(attrib.normals[n], attrib.normals[n + 1],
                                      attrib.normals[n + 2]);
        }
        if (all_uvs) {
            const size_t t = static_cast<size_t>(index.texcoord_index) * 2;
            if (t + 1 >= attrib.texcoords.size()) {
                throw Error(file + ": texture coordinate index " +
                            std::to_string(index.texcoord_index) + " out of range");
            }
            mesh.uvs.emplace_back(attrib.texcoords[t], attrib.texcoords[t + 1]);
        }
        const auto created = static_cast<unsigned>(mesh.positions.size() - 1);
        vertex_of.emplace(key, created);
        return created;
    };
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& indices = shape.mesh.indices;
        for (size_t face = 0; 3 * face + 2 < indices.size(); ++face) {
            mesh.triangles.push_back({vertex(indices[3 * face]), vertex(indices[3 * face + 1]),
                                      vertex(indices[3 * face + 2])});
            const int material =
                face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
            mesh.materials.push_back(material);
        }
    }
    for (glm::vec3& n : mesh.normals) {
        const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (!(length > 0.0f) || !std::isfinite(length)) {
            mesh.normals.clear();  // unusable normals: shade flat
            break;
        }
        n /= length;
    }
    return data;
}

}  // namespace rc
