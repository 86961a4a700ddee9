#include "scene/pbrt_shapes.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <glm/geometric.hpp>

#include "scene/generated_meshes.h"
#include "scene/ply_header.h"
#include "util/error.h"
#include "util/log.h"
#include "util/text.h"

namespace rc {

bool is_pbrt_shape_supported(const std::string& type) {
    return type == "trianglemesh" || type == "bilinearmesh" || type == "plymesh" ||
           type == "sphere";
}

namespace {

// Whether the quad a b c d lies in one plane (to a relative 1e-5 of its size): then its two
// triangles are exactly pbrt's bilinear patch.
bool planar(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const glm::dvec3 n = glm::cross(glm::dvec3(c) - glm::dvec3(a), glm::dvec3(d) - glm::dvec3(b));
    const double size =
        glm::length(glm::dvec3(c) - glm::dvec3(a)) + glm::length(glm::dvec3(d) - glm::dvec3(b));
    const double length = glm::length(n);
    if (!(length > 0.0)) {
        return true;  // degenerate: its triangles are dropped or flat
    }
    return std::abs(glm::dot(n / length, glm::dvec3(d) - glm::dvec3(a))) <= 1e-5 * size;
}

// Each of the `corners` indices of the face from indices[first] names one of the vertices.
void check_face(const std::vector<double>& indices, size_t first, size_t corners, size_t vertices,
                const PbrtParams& params) {
    for (size_t k = 0; k < corners; ++k) {
        const double index = indices[first + k];
        if (!(index >= 0.0 && index < static_cast<double>(vertices))) {
            params.fail("index " + excerpt(std::to_string(static_cast<long long>(index))) +
                        " out of range (" + std::to_string(vertices) + " vertices)");
        }
    }
}

// The "integer indices" of a mesh of faces of `corners` vertices; a mesh of a single `face` may
// omit them (its vertices in order).
std::vector<double> face_indices(PbrtParams& params, const TriangleMesh& mesh, size_t corners,
                                 const std::string& face) {
    std::vector<double> indices = params.get_numbers("indices", {"integer"}, corners);
    if (indices.empty()) {
        if (mesh.positions.size() != corners) {
            params.fail("\"integer indices\" is missing (only a single " + face + " may omit it)");
        }
        for (size_t k = 0; k < corners; ++k) {
            indices.push_back(static_cast<double>(k));
        }
    }
    return indices;
}

// P, N and uv of a mesh shape; N and uv, when given, one per vertex.
TriangleMesh mesh_vertices(PbrtParams& params) {
    TriangleMesh mesh;
    const std::vector<double> p = params.get_numbers("P", {"point3", "point"}, 3);
    if (p.empty()) {
        params.fail("parameter \"point3 P\" is missing");
    }
    for (size_t i = 0; i < p.size(); i += 3) {
        mesh.positions.emplace_back(p[i], p[i + 1], p[i + 2]);
    }
    const std::vector<double> n = params.get_numbers("N", {"normal", "normal3"}, 3);
    if (!n.empty() && n.size() != p.size()) {
        params.fail("\"normal N\" has " + std::to_string(n.size() / 3) + " normals for " +
                    std::to_string(p.size() / 3) + " vertices");
    }
    for (size_t i = 0; i < n.size(); i += 3) {
        const glm::vec3 normal(n[i], n[i + 1], n[i + 2]);
        const float length = glm::length(normal);
        mesh.normals.push_back(length > 0.0f ? normal / length : glm::vec3(0, 0, 1));
    }
    const std::vector<double> uv = params.get_numbers("uv", {"point2"}, 2);
    if (!uv.empty() && uv.size() / 2 != p.size() / 3) {
        params.fail("\"point2 uv\" has " + std::to_string(uv.size() / 2) + " entries for " +
                    std::to_string(p.size() / 3) + " vertices");
    }
    for (size_t i = 0; i < uv.size(); i += 2) {
        mesh.uvs.emplace_back(uv[i], uv[i + 1]);
    }
    params.ignore("faceIndices");  // per-face ids of Ptex textures only
    return mesh;
}

TriangleMesh triangle_mesh(PbrtParams& params) {
    TriangleMesh mesh = mesh_vertices(params);
    const std::vector<double> indices = face_indices(params, mesh, 3, "triangle");
    for (size_t i = 0; i < indices.size(); i += 3) {
        check_face(indices, i, 3, mesh.positions.size(), params);
        mesh.triangles.emplace_back(indices[i], indices[i + 1], indices[i + 2]);
    }
    return mesh;
}

// pbrt's patch p00 p10 p01 p11 (indices in that order) as triangles p00 p10 p11, p00 p11 p01:
// the winding of its normal cross(p10 - p00, p01 - p00).
TriangleMesh bilinear_mesh(PbrtParams& params) {
    TriangleMesh mesh = mesh_vertices(params);
    const std::vector<double> indices = face_indices(params, mesh, 4, "patch");
    bool warned = false;
    for (size_t i = 0; i < indices.size(); i += 4) {
        check_face(indices, i, 4, mesh.positions.size(), params);
        const glm::uvec4 q(indices[i], indices[i + 1], indices[i + 2], indices[i + 3]);
        mesh.triangles.emplace_back(q.x, q.y, q.w);
        mesh.triangles.emplace_back(q.x, q.w, q.z);
        const auto& p = mesh.positions;
        if (!warned && !planar(p[q.x], p[q.y], p[q.w], p[q.z])) {
            log_warning(params.what() +
                        ": a non-planar bilinear patch is rendered as two triangles");
            warned = true;
        }
    }
    return mesh;
}

TriangleMesh sphere_mesh(PbrtParams& params) {
    const float radius = params.get_float("radius", 1.0f);
    const float zmin = params.get_float("zmin", -radius);
    const float zmax = params.get_float("zmax", radius);
    const float phimax = params.get_float("phimax", 360.0f);
    if (!(radius > 0.0f)) {
        params.fail("radius must be positive");
    }
    if (zmin > -radius || zmax < radius || phimax < 360.0f) {
        params.refuse("partial spheres (zmin, zmax, phimax) are not supported");
    }
    log_warning(params.what() + ": the sphere is tessellated into triangles (48 x 96)");
    return make_uv_sphere(glm::vec3(0.0f), radius);
}

}  // namespace

TriangleMesh load_ply_mesh(const std::string& bytes, const std::string& what) {
    check_ply_header(bytes, what);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(),
                                                       aiProcess_ValidateDataStructure, "ply");
    if (scene == nullptr || scene->mNumMeshes == 0) {
        const std::string reason = importer.GetErrorString();
        throw Error(what + ": not a readable PLY mesh" +
                    (reason.empty() ? std::string() : ": " + excerpt(reason, 200)));
    }
    TriangleMesh result;
    bool warned = false;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh& mesh = *scene->mMeshes[m];
        TriangleMesh part;
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            part.positions.emplace_back(p.x, p.y, p.z);
            if (mesh.mNormals != nullptr) {
                const glm::vec3 n(mesh.mNormals[v].x, mesh.mNormals[v].y, mesh.mNormals[v].z);
                const float length = glm::length(n);
                part.normals.push_back(length > 0.0f ? n / length : glm::vec3(0, 0, 1));
            }
            if (mesh.mTextureCoords[0] != nullptr) {
                part.uvs.emplace_back(mesh.mTextureCoords[0][v].x, mesh.mTextureCoords[0][v].y);
            }
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3 && face.mNumIndices != 4) {
                throw Error(what + ": PLY face " + std::to_string(f) + " has " +
                            std::to_string(face.mNumIndices) +
                            " vertices (triangles and quads only)");
            }
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices) {
                    throw Error(what + ": PLY face " + std::to_string(f) + ": index " +
                                std::to_string(face.mIndices[k]) + " out of range");
                }
            }
            const unsigned* i = face.mIndices;
            part.triangles.emplace_back(i[0], i[1], i[2]);
            if (face.mNumIndices == 4) {
                part.triangles.emplace_back(i[0], i[2], i[3]);
                const auto& p = part.positions;
                if (!warned && !planar(p[i[0]], p[i[1]], p[i[2]], p[i[3]])) {
                    log_warning(what + ": a non-planar quad is rendered as two triangles");
                    warned = true;
                }
            }
        }
        result.append(part);
    }
    if (result.triangles.empty()) {
        throw Error(what + ": the PLY file has no faces");
    }
    return result;
}

TriangleMesh pbrt_shape_mesh(const std::string& type, PbrtParams& params,
                             const std::filesystem::path& dir, const SceneFiles& files) {
    if (params.has("alpha")) {
        params.refuse("alpha cut-outs are not supported");
    }
    if (type == "trianglemesh") {
        return triangle_mesh(params);
    }
    if (type == "bilinearmesh") {
        return bilinear_mesh(params);
    }
    if (type == "sphere") {
        return sphere_mesh(params);
    }
    if (params.has("displacement")) {
        params.refuse("displacement is not supported");
    }
    params.ignore("edgelength");  // the displacement's tessellation
    const std::string name = params.get_string("filename", "");
    if (name.empty()) {
        params.fail("parameter \"string filename\" is missing");
    }
    const std::filesystem::path path =
        std::filesystem::path(name).is_absolute() ? std::filesystem::path(name) : dir / name;
    const std::string what = params.what() + ": " + excerpt(path.string());
    if (!files.exists(path)) {
        throw Error(what + ": PLY file not found");
    }
    return load_ply_mesh(files.read(path, kMaxMeshFileBytes, "PLY file"), what);
}

}  // namespace rc
