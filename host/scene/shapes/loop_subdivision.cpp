#include "scene/shapes/loop_subdivision.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <glm/geometric.hpp>
#include <memory>
#include <string>
#include <vector>

#include "util/error.h"

namespace rc {
namespace {

using namespace OpenSubdiv;

// A position as OpenSubdiv's primvar refiner combines them.
struct Point {
    glm::vec3 p{0.0f};
    void Clear(void* = nullptr) { p = glm::vec3(0.0f); }
    void AddWithWeight(const Point& source, float weight) { p += weight * source.p; }
};

std::unique_ptr<Far::TopologyRefiner> loop_refiner(const TriangleMesh& control,
                                                   const std::vector<int>& corners) {
    Far::TopologyDescriptor descriptor;
    descriptor.numVertices = static_cast<int>(control.positions.size());
    descriptor.numFaces = static_cast<int>(control.triangles.size());
    const std::vector<int> per_face(control.triangles.size(), 3);
    descriptor.numVertsPerFace = per_face.data();
    descriptor.vertIndicesPerFace = corners.data();
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    return std::unique_ptr<Far::TopologyRefiner>(
        Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_LOOP, options)));
}

}  // namespace

TriangleMesh make_loop_subdivision(const TriangleMesh& control, int levels) {
    const size_t triangles = control.triangles.size() << (2 * levels);
    if (levels < 0 || levels > 12 || triangles > kMaxSubdividedTriangles) {
        throw Error(std::to_string(control.triangles.size()) + " triangles subdivided " +
                    std::to_string(levels) + " times exceed " +
                    std::to_string(kMaxSubdividedTriangles) + " triangles");
    }
    std::vector<int> corners;
    corners.reserve(3 * control.triangles.size());
    for (const glm::uvec3& t : control.triangles) {
        corners.insert(corners.end(),
                       {static_cast<int>(t.x), static_cast<int>(t.y), static_cast<int>(t.z)});
    }
    const std::unique_ptr<Far::TopologyRefiner> refiner = loop_refiner(control, corners);
    if (!refiner) {
        throw Error("OpenSubdiv could not build the control mesh's topology");
    }
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;  // the limit evaluation needs the finest level's edges
    refiner->RefineUniform(uniform);
    // Step 1: Loop's refinement rules, level by level, into one buffer of every level's vertices.
    std::vector<Point> vertices(refiner->GetNumVerticesTotal());
    for (size_t i = 0; i < control.positions.size(); ++i) {
        vertices[i].p = control.positions[i];
    }
    const Far::PrimvarRefiner primvars(*refiner);
    Point* source = vertices.data();
    for (int level = 1; level <= levels; ++level) {
        Point* destination = source + refiner->GetLevel(level - 1).GetNumVertices();
        primvars.Interpolate(level, source, destination);
        source = destination;
    }
    // Step 2: the finest vertices pushed to the limit surface, with its tangents.
    const Far::TopologyLevel& finest = refiner->GetLevel(levels);
    const int count = finest.GetNumVertices();
    std::vector<Point> limit(count), tangent_u(count), tangent_v(count);
    primvars.Limit(source, limit, tangent_u, tangent_v);
    TriangleMesh mesh;
    mesh.positions.reserve(count);
    mesh.normals.reserve(count);
    for (int i = 0; i < count; ++i) {
        mesh.positions.push_back(limit[i].p);
        const glm::vec3 n = glm::cross(tangent_u[i].p, tangent_v[i].p);
        const float length = glm::length(n);
        mesh.normals.push_back(length > 0.0f ? n / length : glm::vec3(0.0f));
    }
    for (int f = 0; f < finest.GetNumFaces(); ++f) {
        const Far::ConstIndexArray v = finest.GetFaceVertices(f);
        mesh.triangles.emplace_back(v[0], v[1], v[2]);
    }
    // A vertex whose tangents are parallel (a degenerate corner) gets the mesh flat-shaded
    // rather than a zero normal.
    for (const glm::vec3& n : mesh.normals) {
        if (n == glm::vec3(0.0f)) {
            mesh.normals.clear();
            break;
        }
    }
    return mesh;
}

}  // namespace rc
