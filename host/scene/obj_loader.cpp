#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
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
        if (keyword == "v") {
            ++vertices_so_far;
            for (int axis = 0; axis < 3; ++axis) {
                std::string token;
                if (!(tokens >> token)) {
                    throw Error(where + "vertex has fewer than three coordinates");
                }
                errno = 0;
                char* end = nullptr;
                const double value = std::strtod(token.c_str(), &end);
                if (end == token.c_str() || *end != '\0') {
                    throw Error(where + "vertex coordinate '" + token + "' is not a number");
                }
                if (!std::isfinite(value) || !std::isfinite(static_cast<float>(value))) {
                    throw Error(where + "vertex coordinate '" + token + "' is not finite");
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

TriangleMesh load_obj(const std::filesystem::path& path) {
    const std::string file = path.string();
    const std::string text = read_file(path);
    validate_obj_text(text, file);

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = path.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config)) {
        throw Error(file + ": cannot parse OBJ: " + reader.Error());
    }
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    TriangleMesh mesh;
    mesh.positions.reserve(attrib.vertices.size() / 3);
    for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
        mesh.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1],
                                    attrib.vertices[i + 2]);
    }
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        for (size_t i = 0; i + 2 < indices.size(); i += 3) {
            glm::uvec3 triangle;
            for (int k = 0; k < 3; ++k) {
                const int index = indices[i + k].vertex_index;
                if (index < 0 || static_cast<size_t>(index) >= mesh.positions.size()) {
                    throw Error(file + ": shape '" + shape.name + "': vertex index " +
                                std::to_string(index) + " out of range");
                }
                triangle[k] = static_cast<unsigned>(index);
            }
            mesh.triangles.push_back(triangle);
        }
    }
    return mesh;
}

}  // namespace rc
