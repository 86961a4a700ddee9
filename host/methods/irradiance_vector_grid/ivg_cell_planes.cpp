#include "methods/irradiance_vector_grid/ivg_cell_planes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_map>

#include "methods/irradiance_vector_grid/triangle_box_overlap.h"

namespace rc {
namespace {

// The margins, relative to the largest coordinate magnitude s of the scene and the grid (floats
// carry 2^-24 s there). The cell margin covers a ray origin's offset off its surface (at most 32
// ulps of s plus Wächter and Binder's 256 ulps, kernels/common/ray_offset.h) many times over; the
// plane tolerance allows a few ulps of vertex rounding (rotated rectangles); the origin margin
// (32 ulps of s, as the ray offset's own error bound) keeps the ray origin clear of every
// triangle of the plane by more than the float error of the kernel's side test.
constexpr double kCellMargin = 1.0 / 4096.0;
constexpr double kPlaneTolerance = 1.0 / 4194304.0;  // 2^-22
constexpr double kOriginMargin = 1.0 / 524288.0;     // 2^-19

constexpr int32_t kNoTriangle = -1;
constexpr int32_t kSeveralPlanes = -2;

struct Plane {
    glm::dvec3 normal{0.0};  // unit; zero for a triangle of (numerically) no area
    double offset = 0.0;     // dot(normal, x) on the plane
};

Plane triangle_plane(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    Plane plane;
    if (length > 0.0) {
        plane.normal = n / length;
        plane.offset = glm::dot(plane.normal, a);
    }
    return plane;
}

bool within(const Plane& plane, const glm::dvec3& x, double tolerance) {
    return std::fabs(glm::dot(plane.normal, x) - plane.offset) <= tolerance;
}

double largest_magnitude(const TriangleMesh& mesh, const shared::IvgParams& p) {
    double s = 0.0;
    for (const glm::vec3& x : mesh.positions) {
        s = std::max({s, std::fabs(double(x.x)), std::fabs(double(x.y)), std::fabs(double(x.z))});
    }
    const double corner[3] = {double(p.origin.x) + double(p.cells.x) * p.cell.x,
                              double(p.origin.y) + double(p.cells.y) * p.cell.y,
                              double(p.origin.z) + double(p.cells.z) * p.cell.z};
    const double origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    for (int axis = 0; axis < 3; ++axis) {
        s = std::max({s, std::fabs(corner[axis]), std::fabs(origin[axis])});
    }
    return std::max(s, 1e-30);
}

// The world coordinate of grid plane `index` along an axis, as the kernel computes it
// (rc_ivg_corner_position: origin + index * cell in float).
double grid_plane(float origin, float cell, int index) {
    return static_cast<double>(origin + static_cast<float>(index) * cell);
}

// The cells along one axis whose grown extent can overlap [lower, upper].
void cell_range(float origin, float cell, int cells, double lower, double upper, double grow,
                int* first, int* last) {
    *first =
        std::clamp(static_cast<int>(std::floor((lower - grow - origin) / cell)) - 1, 0, cells - 1);
    *last =
        std::clamp(static_cast<int>(std::floor((upper + grow - origin) / cell)) + 1, 0, cells - 1);
}

}  // namespace

IvgCellPlanes classify_cell_planes(const TriangleMesh& mesh, const shared::IvgParams& p) {
    IvgCellPlanes result;
    const double s = largest_magnitude(mesh, p);
    result.cell_margin = static_cast<float>(kCellMargin * s);
    result.origin_margin = static_cast<float>(kOriginMargin * s);
    const double grow = 2.0 * static_cast<double>(result.cell_margin);
    const double tolerance = kPlaneTolerance * s;
    const int cells[3] = {p.cells.x, p.cells.y, p.cells.z};
    const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
    const size_t cell_count = static_cast<size_t>(cells[0]) * cells[1] * cells[2];
    // Step 1: per cell, its first overlapping triangle, or kSeveralPlanes once a triangle off
    // that triangle's plane overlaps it too.
    std::vector<int32_t> first(cell_count, kNoTriangle);
    std::vector<Plane> planes(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3& index = mesh.triangles[t];
        const glm::dvec3 v[3] = {glm::dvec3(mesh.positions[index.x]),
                                 glm::dvec3(mesh.positions[index.y]),
                                 glm::dvec3(mesh.positions[index.z])};
        planes[t] = triangle_plane(v[0], v[1], v[2]);
        const glm::dvec3 lower = glm::min(v[0], glm::min(v[1], v[2]));
        const glm::dvec3 upper = glm::max(v[0], glm::max(v[1], v[2]));
        int from[3];
        int to[3];
        for (int axis = 0; axis < 3; ++axis) {
            cell_range(origin[axis], cell[axis], cells[axis], lower[axis], upper[axis], grow,
                       &from[axis], &to[axis]);
        }
        for (int k = from[2]; k <= to[2]; ++k) {
            for (int j = from[1]; j <= to[1]; ++j) {
                for (int i = from[0]; i <= to[0]; ++i) {
                    const size_t c = (static_cast<size_t>(k) * cells[1] + j) * cells[0] + i;
                    if (first[c] == kSeveralPlanes) {
                        continue;
                    }
                    const glm::dvec3 box_lower(grid_plane(origin[0], cell[0], i) - grow,
                                               grid_plane(origin[1], cell[1], j) - grow,
                                               grid_plane(origin[2], cell[2], k) - grow);
                    const glm::dvec3 box_upper(grid_plane(origin[0], cell[0], i + 1) + grow,
                                               grid_plane(origin[1], cell[1], j + 1) + grow,
                                               grid_plane(origin[2], cell[2], k + 1) + grow);
                    if (!triangle_overlaps_box(v[0], v[1], v[2], box_lower, box_upper)) {
                        continue;
                    }
                    if (first[c] == kNoTriangle) {
                        first[c] = static_cast<int32_t>(t);
                        continue;
                    }
                    const Plane& plane = planes[static_cast<size_t>(first[c])];
                    const bool coplanar =
                        plane.normal != glm::dvec3(0.0) && planes[t].normal != glm::dvec3(0.0) &&
                        within(plane, v[0], tolerance) && within(plane, v[1], tolerance) &&
                        within(plane, v[2], tolerance);
                    if (!coplanar) {
                        first[c] = kSeveralPlanes;
                    }
                }
            }
        }
    }
    // Step 2: the distinct planes (one per first triangle, in cell order) and each cell's index.
    result.cell_planes.assign(cell_count, -1);
    std::unordered_map<int32_t, int32_t> plane_of_triangle;
    for (size_t c = 0; c < cell_count; ++c) {
        if (first[c] == kNoTriangle) {
            ++result.empty_cells;
            continue;
        }
        if (first[c] == kSeveralPlanes) {
            ++result.multi_plane_cells;
            continue;
        }
        const Plane& plane = planes[static_cast<size_t>(first[c])];
        if (plane.normal == glm::dvec3(0.0)) {
            continue;
        }
        const auto found = plane_of_triangle.find(first[c]);
        if (found != plane_of_triangle.end()) {
            result.cell_planes[c] = found->second;
            continue;
        }
        const int32_t index = static_cast<int32_t>(result.planes.size());
        plane_of_triangle.emplace(first[c], index);
        shared::IvgPlane stored{};
        stored.equation = {static_cast<float>(plane.normal.x), static_cast<float>(plane.normal.y),
                           static_cast<float>(plane.normal.z), static_cast<float>(-plane.offset)};
        result.planes.push_back(stored);
        result.cell_planes[c] = index;
    }
    return result;
}

}  // namespace rc
