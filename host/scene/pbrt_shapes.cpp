#include "scene/pbrt_shapes.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <utility>

#include "scene/generated_meshes.h"
#include "scene/ply_mesh.h"
#include "scene/shapes/cylinder.h"
#include "scene/shapes/disk.h"
#include "scene/shapes/loop_subdivision.h"
#include "util/error.h"
#include "util/gzip.h"
#include "util/log.h"
#include "util/text.h"

namespace rc {

bool is_pbrt_shape_supported(const std::string& type) {
    return type == "trianglemesh" || type == "bilinearmesh" || type == "plymesh" ||
           type == "sphere" || type == "disk" || type == "cylinder" || type == "loopsubdiv";
}

namespace {

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
        if (!warned && !is_planar_quad(p[q.x], p[q.y], p[q.w], p[q.z])) {
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

// pbrt's "phimax" in degrees, in (0, 360] (pbrt clamps it into [0, 360]; 0 is no surface).
float phi_max_degrees(PbrtParams& params) {
    const float phi_max = params.get_float("phimax", 360.0f);
    if (!(phi_max > 0.0f && phi_max <= 360.0f)) {
        params.fail("phimax must lie in (0, 360] degrees");
    }
    return phi_max;
}

TriangleMesh disk_mesh(PbrtParams& params) {
    DiskShape disk;
    disk.height = params.get_float("height", 0.0f);
    disk.radius = params.get_float("radius", 1.0f);
    disk.inner_radius = params.get_float("innerradius", 0.0f);
    disk.phi_max_degrees = phi_max_degrees(params);
    if (!std::isfinite(disk.height)) {
        params.fail("height must be finite");
    }
    if (!(disk.radius > 0.0f) || !std::isfinite(disk.radius)) {
        params.fail("radius must be positive and finite");
    }
    if (!(disk.inner_radius >= 0.0f && disk.inner_radius < disk.radius)) {
        params.fail("innerradius must lie in [0, radius)");
    }
    return make_disk(disk);
}

TriangleMesh cylinder_mesh(PbrtParams& params) {
    CylinderShape cylinder;
    cylinder.radius = params.get_float("radius", 1.0f);
    cylinder.z_min = params.get_float("zmin", -1.0f);
    cylinder.z_max = params.get_float("zmax", 1.0f);
    cylinder.phi_max_degrees = phi_max_degrees(params);
    if (!(cylinder.radius > 0.0f) || !std::isfinite(cylinder.radius)) {
        params.fail("radius must be positive and finite");
    }
    if (!std::isfinite(cylinder.z_min) || !std::isfinite(cylinder.z_max) ||
        cylinder.z_min == cylinder.z_max) {
        params.fail("zmin and zmax must be finite and differ");
    }
    if (cylinder.z_min > cylinder.z_max) {
        std::swap(cylinder.z_min, cylinder.z_max);  // as pbrt-v4 orders them
    }
    return make_cylinder(cylinder);
}

// pbrt-v4's loopsubdiv: "point3 P", "integer indices" (triangles), "integer levels" (3).
TriangleMesh loop_subdivision_mesh(PbrtParams& params) {
    const int levels = params.get_int("levels", 3);
    if (levels < 0 || levels > 12) {
        params.fail("levels must lie in [0, 12], got " + std::to_string(levels));
    }
    const TriangleMesh control = triangle_mesh(params);
    try {
        return make_loop_subdivision(control, levels);
    } catch (const Error& error) {
        params.refuse(error.what());
    }
}

}  // namespace

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
    if (type == "disk") {
        return disk_mesh(params);
    }
    if (type == "cylinder") {
        return cylinder_mesh(params);
    }
    if (type == "loopsubdiv") {
        return loop_subdivision_mesh(params);
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
    std::string bytes = files.read(path, kMaxMeshFileBytes, "PLY file");
    if (is_gzip(bytes)) {
        bytes = gunzip(bytes, kMaxMeshFileBytes, what);  // pbrt-v4 reads .ply.gz
    }
    return load_ply_mesh(bytes, what);
}

}  // namespace rc
