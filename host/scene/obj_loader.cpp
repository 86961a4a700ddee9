#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>

#include "util/error.h"
#include "util/text.h"

namespace rc {
namespace {

// One whitespace-separated number of a line: finite in single precision, else Error at `where`.
double finite_number(const std::string& token, const std::string& where, const std::string& what) {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0') {
        throw Error(where + what + " '" + excerpt(token) + "' is not a number");
    }
    if (!std::isfinite(value) || !std::isfinite(static_cast<float>(value))) {
        throw Error(where + what + " '" + excerpt(token) + "' is not finite");
    }
    return value;
}

long long count_vertices(const std::string& text) {
    long long total = 0;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream tokens(line);
        std::string keyword;
        if (tokens >> keyword && keyword == "v") {
            ++total;
        }
    }
    return total;
}

// tinyobjloader counts a face's corners in a byte: larger faces are fanned into triangles in the
// text before it reads them.
constexpr int kMaxParsedCorners = 255;

// The corners of a face line (returned): each index names an existing vertex; at least three.
int validate_face(std::istringstream& tokens, long long vertices_so_far, long long vertex_total,
                  const std::string& where) {
    std::string corner;
    int corners = 0;
    while (tokens >> corner) {
        ++corners;
        const std::string index_text = corner.substr(0, corner.find('/'));
        char* end = nullptr;
        errno = 0;
        const long long index = std::strtoll(index_text.c_str(), &end, 10);
        if (index_text.empty() || *end != '\0' || errno != 0) {
            throw Error(where + "face index '" + excerpt(corner) + "' is not an integer");
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
    return corners;
}

// tinyobjloader reads "nan" and "inf" as 0 and does not report line numbers, so vertex and face
// lines are checked here before it parses the file. True when a face has more corners than
// tinyobjloader can count.
bool validate_obj_text(const std::string& text, const std::string& file) {
    bool large_faces = false;
    const long long vertex_total = count_vertices(text);
    std::istringstream lines(text);
    std::string line;
    long long vertices_so_far = 0;
    long long number = 0;
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
                finite_number(token, where, std::string(what) + " coordinate");
            }
        } else if (keyword == "f") {
            large_faces =
                validate_face(tokens, vertices_so_far, vertex_total, where) > kMaxParsedCorners ||
                large_faces;
        }
    }
    return large_faces;
}

// The text with every face of more than kMaxParsedCorners corners replaced by its fan of
// triangles from its first corner (linear in the corners: the 200 000-corner face).
std::string fan_large_faces(const std::string& text) {
    std::string fanned;
    fanned.reserve(text.size() + text.size() / 4);
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream tokens(line.substr(0, line.find('#')));
        std::string keyword;
        std::vector<std::string> corners;
        if (tokens >> keyword && keyword == "f") {
            for (std::string corner; tokens >> corner;) {
                corners.push_back(corner);
            }
        }
        if (corners.size() <= static_cast<size_t>(kMaxParsedCorners)) {
            fanned += line + "\n";
            continue;
        }
        for (size_t k = 1; k + 1 < corners.size(); ++k) {
            fanned += "f " + corners[0] + " " + corners[k] + " " + corners[k + 1] + "\n";
        }
    }
    return fanned;
}

// The ranges of the MTL values radcache reads (docs/scene-format.md): reflectances in [0, 1],
// emission in [0, 1e9], the Phong exponent Ns in [0, 1e6].
struct MtlRange {
    const char* keyword;
    int count;  // numbers on the line (at least one; Kd 0.5 is grey)
    double min;
    double max;
};
constexpr MtlRange kMtlRanges[] = {
    {"Kd", 3, 0.0, 1.0}, {"Ks", 3, 0.0, 1.0}, {"Ka", 3, 0.0, 1.0},
    {"Ke", 3, 0.0, 1e9}, {"Ns", 1, 0.0, 1e6},
};

// tinyobjloader reads "nan" as 0 and accepts any value: the values radcache uses are checked here,
// with the file and line, as the scene file's are.
void validate_mtl_text(const std::string& text, const std::string& file) {
    std::istringstream lines(text);
    long long number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        std::istringstream tokens(line.substr(0, line.find('#')));
        std::string keyword;
        if (!(tokens >> keyword)) {
            continue;
        }
        for (const MtlRange& range : kMtlRanges) {
            if (keyword != range.keyword) {
                continue;
            }
            const std::string where = file + ":" + std::to_string(number) + ": ";
            int read = 0;
            for (std::string token; read < range.count && tokens >> token; ++read) {
                const double value = finite_number(token, where, keyword + " value");
                if (value < range.min || value > range.max) {
                    char bounds[64];
                    std::snprintf(bounds, sizeof bounds, "[%g, %g]", range.min, range.max);
                    throw Error(where + keyword + " value " + excerpt(token) + " outside " +
                                bounds);
                }
            }
            if (read == 0) {
                throw Error(where + keyword + " has no value");
            }
        }
    }
}

// MTL libraries read through the scene's files (regular files within the size limit) and
// validated before tinyobjloader parses them. A missing library is a warning (tinyobjloader's).
class ValidatingMaterialReader : public tinyobj::MaterialReader {
   public:
    ValidatingMaterialReader(const std::filesystem::path& directory, const SceneFiles& files)
        : directory_(directory), files_(files) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warning,
                    std::string* error) override {
        const std::filesystem::path path = directory_ / name;
        if (!files_.exists(path)) {
            *warning += "material library '" + excerpt(path.string()) + "' not found\n";
            return false;
        }
        const std::string text = files_.read(path, kMaxMaterialFileBytes, "material library");
        validate_mtl_text(text, path.string());
        std::istringstream stream(text);
        tinyobj::LoadMtl(names, materials, &stream, warning, error);
        return true;
    }

   private:
    std::filesystem::path directory_;
    const SceneFiles& files_;
};

// tinyobjloader's warnings, a line each, prefixed with the file. Where a material library is
// missing (our own line), its "Failed to load material file(s)" and its "material [ 'a' ] not
// found in .mtl" lines are folded into that one: the library, and the materials it would have held.
std::vector<std::string> obj_warnings(const std::string& warning, const std::string& file) {
    std::vector<std::string> lines, missing;
    int library = -1;  // our "material library ... not found" line
    std::istringstream in(warning);
    for (std::string line; std::getline(in, line);) {
        const size_t open = line.find("material [ '");
        const size_t close = line.find("' ] not found in .mtl");
        if (line.empty()) {
            continue;
        } else if (line.rfind("material library '", 0) == 0) {
            library = library < 0 ? static_cast<int>(lines.size()) : library;
            lines.push_back(line);
        } else if (line.rfind("Failed to load material file(s)", 0) == 0) {
            continue;  // said by the library's line; if none, said by the materials' lines
        } else if (open != std::string::npos && close != std::string::npos && close > open) {
            missing.push_back(line.substr(open + 12, close - open - 12));
        } else {
            lines.push_back(line);
        }
    }
    if (!missing.empty()) {
        std::string names;
        for (const std::string& name : missing) {
            names += (names.empty() ? "'" : ", '") + name + "'";
        }
        const std::string said = ": its materials " + names + " get the default material";
        if (library >= 0) {
            lines[static_cast<size_t>(library)] += said;
        } else {
            lines.push_back("no material library defines the materials " + names +
                            ": they get the default material");
        }
    }
    std::vector<std::string> out;
    for (const std::string& line : lines) {
        out.push_back(file + ": " + excerpt(line, 4 * kQuoteLimit));
    }
    return out;
}

ObjMaterial material_of(const tinyobj::material_t& m, const std::filesystem::path& directory) {
    ObjMaterial material;
    material.name = m.name;
    material.kd = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    material.ks = {m.specular[0], m.specular[1], m.specular[2]};
    material.ns = m.shininess;
    material.ke = {m.emission[0], m.emission[1], m.emission[2]};
    if (!m.diffuse_texname.empty()) {
        material.map_kd = directory / m.diffuse_texname;
    }
    return material;
}

// The triangles of a face of n corners (indices into the face's corners): a triangle as it is,
// a quad split along its shorter diagonal (as tinyobjloader splits it), a larger polygon as a fan
// from its first corner.
std::vector<std::array<size_t, 3>> triangulate_face(const tinyobj::attrib_t& attrib,
                                                    const tinyobj::index_t* corners, size_t n) {
    if (n == 4) {
        auto position = [&](size_t c) {
            const size_t v = static_cast<size_t>(corners[c].vertex_index) * 3;
            return glm::vec3(attrib.vertices[v], attrib.vertices[v + 1], attrib.vertices[v + 2]);
        };
        const glm::vec3 d02 = position(2) - position(0);
        const glm::vec3 d13 = position(3) - position(1);
        const float squared02 = d02.x * d02.x + d02.y * d02.y + d02.z * d02.z;
        const float squared13 = d13.x * d13.x + d13.y * d13.y + d13.z * d13.z;
        if (squared02 < squared13) {
            return {{0, 1, 2}, {0, 2, 3}};
        }
        return {{0, 1, 3}, {1, 2, 3}};
    }
    std::vector<std::array<size_t, 3>> triangles;
    for (size_t k = 1; k + 1 < n; ++k) {
        triangles.push_back({0, k, k + 1});
    }
    return triangles;
}

// Every face corner (v, vt, vn) becomes a vertex, shared between corners with the same triple.
void build_mesh(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                const std::string& file, TriangleMesh& mesh) {
    bool all_normals = true;
    bool all_uvs = true;
    const size_t vertex_count = attrib.vertices.size() / 3;
    for (const tinyobj::shape_t& shape : shapes) {
        for (const tinyobj::index_t& index : shape.mesh.indices) {
            // The text was checked line by line, but tinyobjloader splits lines and words its own
            // way (a vertical tab is not a space to it): its own indices are checked again.
            if (index.vertex_index < 0 || static_cast<size_t>(index.vertex_index) >= vertex_count) {
                throw Error(file + ": vertex index " + std::to_string(index.vertex_index + 1) +
                            " out of range (" + std::to_string(vertex_count) +
                            " vertices as parsed)");
            }
            all_normals = all_normals && index.normal_index >= 0;
            all_uvs = all_uvs && index.texcoord_index >= 0;
        }
    }
    std::map<std::array<int, 3>, unsigned> vertex_of;
    auto vertex = [&](const tinyobj::index_t& index) {
        const std::array<int, 3> key = {index.vertex_index, all_uvs ? index.texcoord_index : -1,
                                        all_normals ? index.normal_index : -1};
        const auto found = vertex_of.find(key);
        if (found != vertex_of.end()) {
            return found->second;
        }
        const size_t v = static_cast<size_t>(index.vertex_index) * 3;
        mesh.positions.emplace_back(attrib.vertices[v], attrib.vertices[v + 1],
                                    attrib.vertices[v + 2]);
        if (all_normals) {
            const size_t n = static_cast<size_t>(index.normal_index) * 3;
            if (n + 2 >= attrib.normals.size()) {
                throw Error(file + ": normal index " + std::to_string(index.normal_index + 1) +
                            " out of range");
            }
            mesh.normals.emplace_back(attrib.normals[n], attrib.normals[n + 1],
                                      attrib.normals[n + 2]);
        }
        if (all_uvs) {
            const size_t t = static_cast<size_t>(index.texcoord_index) * 2;
            if (t + 1 >= attrib.texcoords.size()) {
                throw Error(file + ": texture coordinate index " +
                            std::to_string(index.texcoord_index + 1) + " out of range");
            }
            mesh.uvs.emplace_back(attrib.texcoords[t], attrib.texcoords[t + 1]);
        }
        const auto created = static_cast<unsigned>(mesh.positions.size() - 1);
        vertex_of.emplace(key, created);
        return created;
    };
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& indices = shape.mesh.indices;
        size_t first = 0;
        for (size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            const size_t n = shape.mesh.num_face_vertices[face];
            for (const auto& t : triangulate_face(attrib, &indices[first], n)) {
                mesh.triangles.push_back({vertex(indices[first + t[0]]),
                                          vertex(indices[first + t[1]]),
                                          vertex(indices[first + t[2]])});
                mesh.materials.push_back(
                    face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1);
            }
            first += n;
        }
    }
}

}  // namespace

ObjData load_obj(const std::filesystem::path& path, const SceneFiles& files) {
    const std::string file = path.string();
    std::string text = files.read(path, kMaxMeshFileBytes, "mesh file");
    if (validate_obj_text(text, file)) {
        text = fan_large_faces(text);
    }

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning;
    std::string error;
    std::istringstream stream(text);
    ValidatingMaterialReader material_reader(path.parent_path(), files);
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, &material_reader,
                          /*triangulate=*/false,
                          /*default_vcols_fallback=*/false)) {
        throw Error(file + ": cannot parse OBJ: " + excerpt(error));
    }
    ObjData data;
    data.warnings = obj_warnings(warning, file);
    for (const tinyobj::material_t& m : materials) {
        data.materials.push_back(material_of(m, path.parent_path()));
    }
    build_mesh(attrib, shapes, file, data.mesh);
    for (glm::vec3& n : data.mesh.normals) {
        const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (!(length > 0.0f) || !std::isfinite(length)) {
            data.mesh.normals.clear();  // unusable normals: shade flat
            break;
        }
        n /= length;
    }
    return data;
}

}  // namespace rc
