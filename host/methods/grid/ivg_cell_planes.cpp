#include "methods/grid/ivg_cell_planes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <utility>

#include "methods/grid/triangle_box_overlap.h"

namespace rc {
namespace {

// The margins, relative to the largest coordinate magnitude s of the scene and the grid (floats
// carry 2^-24 s there). The cell margin covers a ray origin's offset off its surface (at most 32
// ulps of s plus Wächter and Binder's 256 ulps, kernels/common/ray_offset.h) many times over; the
// plane tolerance allows a few ulps of vertex rounding (rotated rectangles); the origin margin
// (32 ulps of s, as the ray offset's own error bound) keeps the ray origin clear of every
// triangle behind the plane by more than the float error of the kernel's side test.
constexpr double kCellMargin = 1.0 / 4096.0;
constexpr double kPlaneTolerance = 1.0 / 4194304.0;  // 2^-22
constexpr double kOriginMargin = 1.0 / 524288.0;     // 2^-19
// Distinct planes of a cell's triangles tried as its supporting planes.
constexpr int kCandidatesPerCell = 8;

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

struct Triangles {
    std::vector<std::array<glm::dvec3, 3>> vertices;
    std::vector<Plane> planes;
};

Triangles mesh_triangles(const TriangleMesh& mesh) {
    Triangles t;
    for (const glm::uvec3& index : mesh.triangles) {
        t.vertices.push_back({glm::dvec3(mesh.positions[index.x]),
                              glm::dvec3(mesh.positions[index.y]),
                              glm::dvec3(mesh.positions[index.z])});
        const auto& v = t.vertices.back();
        t.planes.push_back(triangle_plane(v[0], v[1], v[2]));
    }
    return t;
}

// (cell, triangle) for every triangle overlapping a cell grown by `grow`, by cell, then triangle.
std::vector<std::pair<uint32_t, uint32_t>> cell_triangles(const Triangles& t,
                                                          const shared::IvgParams& p, double grow) {
    const int cells[3] = {p.cells.x, p.cells.y, p.cells.z};
    const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (size_t i = 0; i < t.vertices.size(); ++i) {
        const auto& v = t.vertices[i];
        const glm::dvec3 lower = glm::min(v[0], glm::min(v[1], v[2]));
        const glm::dvec3 upper = glm::max(v[0], glm::max(v[1], v[2]));
        int from[3];
        int to[3];
        for (int axis = 0; axis < 3; ++axis) {
            cell_range(origin[axis], cell[axis], cells[axis], lower[axis], upper[axis], grow,
                       &from[axis], &to[axis]);
        }
        for (int z = from[2]; z <= to[2]; ++z) {
            for (int y = from[1]; y <= to[1]; ++y) {
                for (int x = from[0]; x <= to[0]; ++x) {
                    const glm::dvec3 box_lower(grid_plane(origin[0], cell[0], x) - grow,
                                               grid_plane(origin[1], cell[1], y) - grow,
                                               grid_plane(origin[2], cell[2], z) - grow);
                    const glm::dvec3 box_upper(grid_plane(origin[0], cell[0], x + 1) + grow,
                                               grid_plane(origin[1], cell[1], y + 1) + grow,
                                               grid_plane(origin[2], cell[2], z + 1) + grow);
                    if (triangle_overlaps_box(v[0], v[1], v[2], box_lower, box_upper)) {
                        const size_t c = (static_cast<size_t>(z) * cells[1] + y) * cells[0] + x;
                        pairs.emplace_back(static_cast<uint32_t>(c), static_cast<uint32_t>(i));
                    }
                }
            }
        }
    }
    std::stable_sort(pairs.begin(), pairs.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    return pairs;
}

// The sides of a cell's triangles' plane `plane` the triangles [begin, end) of `pairs` leave
// free: +1 (all of them within `tolerance` of the plane or behind it), -1 (in front), both
// (+1 | -1 as bits 0 and 1: all within the tolerance) or none.
int free_sides(const Plane& plane, const Triangles& t,
               const std::vector<std::pair<uint32_t, uint32_t>>& pairs, size_t begin, size_t end,
               double tolerance) {
    double lowest = 0.0;
    double highest = 0.0;
    for (size_t k = begin; k < end; ++k) {
        for (const glm::dvec3& v : t.vertices[pairs[k].second]) {
            const double d = glm::dot(plane.normal, v) - plane.offset;
            lowest = std::min(lowest, d);
            highest = std::max(highest, d);
        }
    }
    return (highest <= tolerance ? 1 : 0) | (lowest >= -tolerance ? 2 : 0);
}

}  // namespace

IvgCellPlanes classify_cell_planes(const TriangleMesh& mesh, const shared::IvgParams& p) {
    IvgCellPlanes result;
    const double s = largest_magnitude(mesh, p);
    result.cell_margin = static_cast<float>(kCellMargin * s);
    result.origin_margin = static_cast<float>(kOriginMargin * s);
    const double tolerance = kPlaneTolerance * s;
    const size_t cell_count = static_cast<size_t>(p.cells.x) * p.cells.y * p.cells.z;
    const Triangles t = mesh_triangles(mesh);
    // Step 1: the triangles overlapping each cell grown by twice the cell margin.
    const std::vector<std::pair<uint32_t, uint32_t>> pairs =
        cell_triangles(t, p, 2.0 * static_cast<double>(result.cell_margin));
    // Step 2: per cell, up to two free sides of the planes of its triangles (in triangle order),
    // each stored once in the table as the plane oriented towards its free side.
    shared::IvgCellPlanes none{};
    none.first = -1;
    none.second = -1;
    result.cell_planes.assign(cell_count, none);
    std::map<std::pair<uint32_t, int>, int32_t> stored;  // (triangle, side) -> table index
    size_t empty = cell_count;
    for (size_t begin = 0; begin < pairs.size();) {
        const uint32_t c = pairs[begin].first;
        size_t end = begin;
        while (end < pairs.size() && pairs[end].first == c) {
            ++end;
        }
        --empty;
        std::vector<int32_t> sides;
        std::vector<const Plane*> tried;
        for (size_t k = begin; k < end && sides.size() < 2 && tried.size() < kCandidatesPerCell;
             ++k) {
            const uint32_t triangle = pairs[k].second;
            const Plane& plane = t.planes[triangle];
            const bool seen = std::any_of(tried.begin(), tried.end(), [&](const Plane* q) {
                return glm::dot(q->normal, plane.normal) > 1.0 - 1e-12 &&
                       std::fabs(q->offset - plane.offset) <= tolerance;
            });
            if (plane.normal == glm::dvec3(0.0) || seen) {
                continue;
            }
            tried.push_back(&plane);
            const int free = free_sides(plane, t, pairs, begin, end, tolerance);
            for (int side = 0; side < 2 && sides.size() < 2; ++side) {
                if ((free & (1 << side)) == 0) {
                    continue;
                }
                const auto key = std::make_pair(triangle, side);
                auto found = stored.find(key);
                if (found == stored.end()) {
                    const double sign = side == 0 ? 1.0 : -1.0;
                    shared::IvgPlane oriented{};
                    oriented.equation = {static_cast<float>(sign * plane.normal.x),
                                         static_cast<float>(sign * plane.normal.y),
                                         static_cast<float>(sign * plane.normal.z),
                                         static_cast<float>(-sign * plane.offset)};
                    found = stored.emplace(key, static_cast<int32_t>(result.planes.size())).first;
                    result.planes.push_back(oriented);
                }
                sides.push_back(found->second);
            }
        }
        if (sides.empty()) {
            ++result.unsupported_cells;
        } else {
            result.cell_planes[c].first = sides[0];
            result.cell_planes[c].second = sides.size() > 1 ? sides[1] : -1;
        }
        begin = end;
    }
    result.empty_cells = empty;
    return result;
}

}  // namespace rc
