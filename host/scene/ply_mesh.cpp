#include "scene/ply_mesh.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <vector>

#include "scene/ply_header.h"
#include "util/error.h"
#include "util/log.h"

namespace rc {
namespace {

// Reads the body's values one at a time, in file order, as numbers (the header check has
// bounded every element and list by the bytes the file holds).
class PlyValues {
   public:
    PlyValues(const std::string& bytes, const PlyHeader& header, const std::string& what)
        : bytes_(bytes), at_(header.body), format_(header.format), what_(what) {}

    double next(const std::string& type) {
        if (format_ == PlyFormat::kAscii) {
            return next_word();
        }
        if (type == "char" || type == "int8") {
            return static_cast<int8_t>(raw(1));
        }
        if (type == "uchar" || type == "uint8") {
            return static_cast<uint8_t>(raw(1));
        }
        if (type == "short" || type == "int16") {
            return static_cast<int16_t>(raw(2));
        }
        if (type == "ushort" || type == "uint16") {
            return static_cast<uint16_t>(raw(2));
        }
        if (type == "int" || type == "int32") {
            return static_cast<int32_t>(raw(4));
        }
        if (type == "uint" || type == "uint32") {
            return static_cast<uint32_t>(raw(4));
        }
        if (type == "float" || type == "float32") {
            const auto bits = static_cast<uint32_t>(raw(4));
            float value;
            std::memcpy(&value, &bits, sizeof value);
            return value;
        }
        const uint64_t bits = raw(8);  // double, float64: the header admits no other type
        double value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }

   private:
    // The next `size` bytes as an unsigned integer in the file's byte order.
    uint64_t raw(size_t size) {
        uint64_t value = 0;
        for (size_t k = 0; k < size; ++k) {
            const size_t byte = format_ == PlyFormat::kBinaryBigEndian ? k : size - 1 - k;
            value = (value << 8) | static_cast<unsigned char>(bytes_[at_ + byte]);
        }
        at_ += size;
        return value;
    }

    double next_word() {
        while (at_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[at_]))) {
            ++at_;
        }
        char* end = nullptr;
        const double value = std::strtod(bytes_.c_str() + at_, &end);
        const auto after = static_cast<size_t>(end - bytes_.c_str());
        if (after == at_) {
            throw Error(what_ + ": PLY body: no number at offset " + std::to_string(at_));
        }
        at_ = after;
        return value;
    }

    const std::string& bytes_;
    size_t at_;
    PlyFormat format_;
    const std::string& what_;
};

// The slot a vertex property fills: position, normal or texture coordinate component, or none.
enum class Slot { kNone, kX, kY, kZ, kNx, kNy, kNz, kU, kV };

Slot slot_of(const std::string& name) {
    if (name == "x") return Slot::kX;
    if (name == "y") return Slot::kY;
    if (name == "z") return Slot::kZ;
    if (name == "nx") return Slot::kNx;
    if (name == "ny") return Slot::kNy;
    if (name == "nz") return Slot::kNz;
    if (name == "u" || name == "s" || name == "texture_u" || name == "texture_s") return Slot::kU;
    if (name == "v" || name == "t" || name == "texture_v" || name == "texture_t") return Slot::kV;
    return Slot::kNone;
}

bool has_slots(const PlyElement& element, Slot first, Slot second) {
    bool a = false;
    bool b = false;
    for (const PlyProperty& p : element.properties) {
        a |= p.count_type.empty() && slot_of(p.name) == first;
        b |= p.count_type.empty() && slot_of(p.name) == second;
    }
    return a && b;
}

void skip_list(PlyValues& values, const PlyProperty& p) {
    const double count = values.next(p.count_type);
    for (double k = 0; k < count; ++k) {
        values.next(p.type);
    }
}

void read_vertices(PlyValues& values, const PlyElement& e, TriangleMesh& mesh,
                   const std::string& what) {
    const bool normals = has_slots(e, Slot::kNx, Slot::kNy) && has_slots(e, Slot::kNz, Slot::kNz);
    const bool uvs = has_slots(e, Slot::kU, Slot::kV);
    for (size_t i = 0; i < e.count; ++i) {
        double v[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
        for (const PlyProperty& p : e.properties) {
            if (!p.count_type.empty()) {
                skip_list(values, p);
                continue;
            }
            const double value = values.next(p.type);
            const Slot slot = slot_of(p.name);
            if (slot != Slot::kNone) {
                v[static_cast<int>(slot)] = value;
            }
        }
        const glm::vec3 position(v[1], v[2], v[3]);
        if (!std::isfinite(position.x) || !std::isfinite(position.y) ||
            !std::isfinite(position.z)) {
            throw Error(what + ": PLY vertex " + std::to_string(i) +
                        " has a coordinate that is not a finite float");
        }
        mesh.positions.push_back(position);
        if (normals) {
            const glm::vec3 n(v[4], v[5], v[6]);
            const float length = glm::length(n);
            mesh.normals.push_back(length > 0.0f && std::isfinite(length) ? n / length
                                                                          : glm::vec3(0, 0, 1));
        }
        if (uvs) {
            mesh.uvs.emplace_back(v[7], v[8]);
        }
    }
}

// One face's index list into *mesh (after the vertices: PLY files put them first).
void add_face(const std::vector<double>& indices, size_t f, size_t vertices, TriangleMesh& mesh,
              bool& warned, const std::string& what) {
    if (indices.size() != 3 && indices.size() != 4) {
        throw Error(what + ": PLY face " + std::to_string(f) + " has " +
                    std::to_string(indices.size()) + " vertices (triangles and quads only)");
    }
    unsigned i[4] = {0, 0, 0, 0};
    for (size_t k = 0; k < indices.size(); ++k) {
        if (!(indices[k] >= 0.0) || indices[k] >= static_cast<double>(vertices)) {
            throw Error(what + ": PLY face " + std::to_string(f) + ": index " +
                        std::to_string(static_cast<long long>(indices[k])) + " out of range (" +
                        std::to_string(vertices) + " vertices)");
        }
        i[k] = static_cast<unsigned>(indices[k]);
    }
    mesh.triangles.emplace_back(i[0], i[1], i[2]);
    if (indices.size() == 4) {
        mesh.triangles.emplace_back(i[0], i[2], i[3]);
        const auto& p = mesh.positions;
        if (!warned && !is_planar_quad(p[i[0]], p[i[1]], p[i[2]], p[i[3]])) {
            log_warning(what + ": a non-planar quad is rendered as two triangles");
            warned = true;
        }
    }
}

void read_faces(PlyValues& values, const PlyElement& e, size_t vertices, TriangleMesh& mesh,
                const std::string& what) {
    bool warned = false;
    std::vector<double> indices;
    for (size_t f = 0; f < e.count; ++f) {
        bool read = false;
        for (const PlyProperty& p : e.properties) {
            const bool wanted = !read && !p.count_type.empty() &&
                                (p.name == "vertex_indices" || p.name == "vertex_index");
            if (!wanted) {
                p.count_type.empty() ? static_cast<void>(values.next(p.type))
                                     : skip_list(values, p);
                continue;
            }
            indices.assign(static_cast<size_t>(values.next(p.count_type)), 0.0);
            for (double& index : indices) {
                index = values.next(p.type);
            }
            add_face(indices, f, vertices, mesh, warned, what);
            read = true;
        }
    }
}

}  // namespace

TriangleMesh load_ply_mesh(const std::string& bytes, const std::string& what) {
    const PlyHeader header = check_ply_header(bytes, what);
    PlyValues values(bytes, header, what);
    TriangleMesh mesh;
    bool have_vertices = false;
    for (const PlyElement& e : header.elements) {
        if (e.name == "vertex" && !have_vertices) {
            read_vertices(values, e, mesh, what);
            have_vertices = true;
        } else if (e.name == "face" && have_vertices) {
            read_faces(values, e, mesh.positions.size(), mesh, what);
        } else if (e.name == "face") {
            throw Error(what + ": PLY faces come before the vertices (not supported)");
        } else {
            for (size_t i = 0; i < e.count; ++i) {  // another element: skipped
                for (const PlyProperty& p : e.properties) {
                    p.count_type.empty() ? static_cast<void>(values.next(p.type))
                                         : skip_list(values, p);
                }
            }
        }
    }
    if (mesh.triangles.empty()) {
        throw Error(what + ": the PLY file has no faces");
    }
    return mesh;
}

}  // namespace rc
