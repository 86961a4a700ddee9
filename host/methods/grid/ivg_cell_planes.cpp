#include "methods/grid/ivg_cell_planes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
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

// Per triangle, 1 when an earlier triangle of the mesh has bitwise the same three vertices in the
// same order. Such a copy changes no cell's classification: its plane is the one already tried
// (or skipped) and its vertices give the same distances. Sorted, not hashed: O(n log n) whatever
// the coordinates.
std::vector<uint8_t> triangle_copies(const TriangleMesh& mesh) {
    using Key = std::array<uint32_t, 9>;
    std::vector<Key> keys(mesh.triangles.size());
    for (size_t i = 0; i < keys.size(); ++i) {
        const glm::uvec3& index = mesh.triangles[i];
        for (int k = 0; k < 3; ++k) {
            std::memcpy(&keys[i][3 * k], &mesh.positions[index[k]], 3 * sizeof(float));
        }
    }
    std::vector<uint32_t> order(keys.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return keys[a] != keys[b] ? keys[a] < keys[b] : a < b;
    });
    // Each run of equal keys: every triangle after the run's first (its lowest index) is a copy.
    std::vector<uint8_t> copy(keys.size(), 0);
    for (size_t k = 1; k < order.size(); ++k) {
        copy[order[k]] = keys[order[k]] == keys[order[k - 1]] ? 1 : 0;
    }
    return copy;
}

// The cells a triangle's bounding box, grown by `grow`, can overlap: [from, to] per axis.
struct CellBox {
    int from[3];
    int to[3];
    size_t count() const {
        return static_cast<size_t>(to[0] - from[0] + 1) * (to[1] - from[1] + 1) *
               (to[2] - from[2] + 1);
    }
};

CellBox triangle_cell_box(const std::array<glm::dvec3, 3>& v, const shared::IvgParams& p,
                          double grow) {
    const glm::dvec3 lower = glm::min(v[0], glm::min(v[1], v[2]));
    const glm::dvec3 upper = glm::max(v[0], glm::max(v[1], v[2]));
    const int cells[3] = {p.cells.x, p.cells.y, p.cells.z};
    const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
    CellBox box;
    for (int axis = 0; axis < 3; ++axis) {
        cell_range(origin[axis], cell[axis], cells[axis], lower[axis], upper[axis], grow,
                   &box.from[axis], &box.to[axis]);
    }
    return box;
}

// Cells that the boxes of the triangles left unclassified reach: +1 at a box's lower corner and
// the inclusion-exclusion signs at its upper corners, summed over the grid once at the end.
class BoxMarks {
   public:
    explicit BoxMarks(const shared::IvgParams& p) : n_{p.cells.x, p.cells.y, p.cells.z} {}

    void add(const CellBox& box) {
        if (marks_.empty()) {
            marks_.assign(static_cast<size_t>(n_[0] + 1) * (n_[1] + 1) * (n_[2] + 1), 0);
        }
        for (int corner = 0; corner < 8; ++corner) {
            int at[3];
            int sign = 1;
            for (int axis = 0; axis < 3; ++axis) {
                const bool upper = ((corner >> axis) & 1) != 0;
                at[axis] = upper ? box.to[axis] + 1 : box.from[axis];
                sign = upper ? -sign : sign;
            }
            marks_[index(at[0], at[1], at[2])] += sign;
        }
    }

    // Per cell (x fastest, then y, z), 1 where a box reaches it; empty when no box was added.
    std::vector<uint8_t> cells() {
        if (marks_.empty()) {
            return {};
        }
        // Step 1: prefix sums along x, then y, then z turn the corner signs into box counts.
        const int step[3] = {1, n_[0] + 1, (n_[0] + 1) * (n_[1] + 1)};
        for (int axis = 0; axis < 3; ++axis) {
            for (int z = 0; z <= n_[2]; ++z) {
                for (int y = 0; y <= n_[1]; ++y) {
                    for (int x = 0; x <= n_[0]; ++x) {
                        const int at[3] = {x, y, z};
                        if (at[axis] > 0) {
                            marks_[index(x, y, z)] += marks_[index(x, y, z) - step[axis]];
                        }
                    }
                }
            }
        }
        // Step 2: the cells with a count.
        std::vector<uint8_t> reached(static_cast<size_t>(n_[0]) * n_[1] * n_[2]);
        for (int z = 0; z < n_[2]; ++z) {
            for (int y = 0; y < n_[1]; ++y) {
                for (int x = 0; x < n_[0]; ++x) {
                    reached[(static_cast<size_t>(z) * n_[1] + y) * n_[0] + x] =
                        marks_[index(x, y, z)] > 0 ? 1 : 0;
                }
            }
        }
        return reached;
    }

   private:
    size_t index(int x, int y, int z) const {
        return (static_cast<size_t>(z) * (n_[1] + 1) + y) * (n_[0] + 1) + x;
    }
    int n_[3];
    std::vector<int32_t> marks_;
};

// The triangles overlapping each cell grown by `grow`: by cell, in mesh order.
struct CellTriangles {
    std::vector<size_t> start;          // per cell, its first entry of `triangles`; one more
    std::vector<uint32_t> triangles;    // the cells' triangles, cell after cell
    std::vector<uint8_t> unclassified;  // per cell, 1: a skipped triangle's box reaches it; or
                                        // empty (none skipped)
    size_t box_tests = 0;
    size_t skipped_triangles = 0;
};

// The cells' triangles, copies left out, at most `budget` triangle-box tests made: a triangle
// whose cell box would overrun the budget is skipped and its whole box left unclassified.
CellTriangles cell_triangles(const Triangles& t, const std::vector<uint8_t>& copy,
                             const shared::IvgParams& p, double grow, size_t budget) {
    const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
    CellTriangles result;
    BoxMarks marks(p);
    // Step 1: (cell, triangle) for each overlap, in triangle order.
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (size_t i = 0; i < t.vertices.size(); ++i) {
        if (copy[i] != 0) {
            continue;
        }
        const auto& v = t.vertices[i];
        const CellBox box = triangle_cell_box(v, p, grow);
        if (box.count() > budget - result.box_tests) {
            marks.add(box);
            ++result.skipped_triangles;
            continue;
        }
        result.box_tests += box.count();
        for (int z = box.from[2]; z <= box.to[2]; ++z) {
            for (int y = box.from[1]; y <= box.to[1]; ++y) {
                for (int x = box.from[0]; x <= box.to[0]; ++x) {
                    const glm::dvec3 box_lower(grid_plane(origin[0], cell[0], x) - grow,
                                               grid_plane(origin[1], cell[1], y) - grow,
                                               grid_plane(origin[2], cell[2], z) - grow);
                    const glm::dvec3 box_upper(grid_plane(origin[0], cell[0], x + 1) + grow,
                                               grid_plane(origin[1], cell[1], y + 1) + grow,
                                               grid_plane(origin[2], cell[2], z + 1) + grow);
                    if (triangle_overlaps_box(v[0], v[1], v[2], box_lower, box_upper)) {
                        const size_t c = (static_cast<size_t>(z) * p.cells.y + y) * p.cells.x + x;
                        pairs.emplace_back(static_cast<uint32_t>(c), static_cast<uint32_t>(i));
                    }
                }
            }
        }
    }
    // Step 2: grouped by cell, keeping the triangle order (a counting sort).
    const size_t cell_count = static_cast<size_t>(p.cells.x) * p.cells.y * p.cells.z;
    result.start.assign(cell_count + 1, 0);
    for (const auto& pair : pairs) {
        ++result.start[pair.first + 1];
    }
    std::partial_sum(result.start.begin(), result.start.end(), result.start.begin());
    std::vector<size_t> next(result.start.begin(), result.start.end() - 1);
    result.triangles.resize(pairs.size());
    for (const auto& pair : pairs) {
        result.triangles[next[pair.first]++] = pair.second;
    }
    result.unclassified = marks.cells();
    return result;
}

// The sides of a cell's triangles' plane `plane` the triangles [begin, end) leave free: +1 (all
// of them within `tolerance` of the plane or behind it), -1 (in front), both (+1 | -1 as bits 0
// and 1: all within the tolerance) or none.
int free_sides(const Plane& plane, const Triangles& t, const uint32_t* begin, const uint32_t* end,
               double tolerance) {
    double lowest = 0.0;
    double highest = 0.0;
    for (const uint32_t* k = begin; k != end; ++k) {
        for (const glm::dvec3& v : t.vertices[*k]) {
            const double d = glm::dot(plane.normal, v) - plane.offset;
            lowest = std::min(lowest, d);
            highest = std::max(highest, d);
        }
    }
    return (highest <= tolerance ? 1 : 0) | (lowest >= -tolerance ? 2 : 0);
}

// The oriented planes (table indices) of a cell: up to two free sides of the planes of its
// triangles [begin, end), tried in that order, each stored once in `planes` as the plane oriented
// towards its free side (`stored`: (triangle, side) -> table index).
std::vector<int32_t> cell_sides(const Triangles& t, const uint32_t* begin, const uint32_t* end,
                                double tolerance,
                                std::map<std::pair<uint32_t, int>, int32_t>& stored,
                                std::vector<shared::IvgPlane>& planes) {
    std::vector<int32_t> sides;
    std::vector<const Plane*> tried;
    for (const uint32_t* k = begin;
         k != end && sides.size() < 2 && tried.size() < kCandidatesPerCell; ++k) {
        const uint32_t triangle = *k;
        const Plane& plane = t.planes[triangle];
        const bool seen = std::any_of(tried.begin(), tried.end(), [&](const Plane* q) {
            return glm::dot(q->normal, plane.normal) > 1.0 - 1e-12 &&
                   std::fabs(q->offset - plane.offset) <= tolerance;
        });
        if (plane.normal == glm::dvec3(0.0) || seen) {
            continue;
        }
        tried.push_back(&plane);
        const int free = free_sides(plane, t, begin, end, tolerance);
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
                found = stored.emplace(key, static_cast<int32_t>(planes.size())).first;
                planes.push_back(oriented);
            }
            sides.push_back(found->second);
        }
    }
    return sides;
}

}  // namespace

IvgCellPlanes classify_cell_planes(const TriangleMesh& mesh, const shared::IvgParams& p,
                                   size_t box_tests_per_element) {
    IvgCellPlanes result;
    const double s = largest_magnitude(mesh, p);
    result.cell_margin = static_cast<float>(kCellMargin * s);
    result.origin_margin = static_cast<float>(kOriginMargin * s);
    const double tolerance = kPlaneTolerance * s;
    const size_t cell_count = static_cast<size_t>(p.cells.x) * p.cells.y * p.cells.z;
    const Triangles t = mesh_triangles(mesh);
    // Step 1: the triangles overlapping each cell grown by twice the cell margin, copies left out,
    // within the budget of triangle-box tests.
    const std::vector<uint8_t> copy = triangle_copies(mesh);
    result.copied_triangles = static_cast<size_t>(std::count(copy.begin(), copy.end(), 1));
    const size_t distinct = copy.size() - result.copied_triangles;
    const size_t budget = box_tests_per_element * (distinct + cell_count);
    const CellTriangles cells =
        cell_triangles(t, copy, p, 2.0 * static_cast<double>(result.cell_margin), budget);
    result.box_tests = cells.box_tests;
    result.skipped_triangles = cells.skipped_triangles;
    // Step 2: per cell, up to two free sides of the planes of its triangles (in triangle order);
    // none where a skipped triangle may reach the cell.
    shared::IvgCellPlanes none{};
    none.first = -1;
    none.second = -1;
    result.cell_planes.assign(cell_count, none);
    std::map<std::pair<uint32_t, int>, int32_t> stored;  // (triangle, side) -> table index
    for (size_t c = 0; c < cell_count; ++c) {
        const uint32_t* begin = cells.triangles.data() + cells.start[c];
        const uint32_t* end = cells.triangles.data() + cells.start[c + 1];
        if (!cells.unclassified.empty() && cells.unclassified[c] != 0) {
            ++result.unsupported_cells;
            continue;
        }
        if (begin == end) {
            ++result.empty_cells;
            continue;
        }
        const std::vector<int32_t> sides =
            cell_sides(t, begin, end, tolerance, stored, result.planes);
        if (sides.empty()) {
            ++result.unsupported_cells;
        } else {
            result.cell_planes[c].first = sides[0];
            result.cell_planes[c].second = sides.size() > 1 ? sides[1] : -1;
        }
    }
    return result;
}

}  // namespace rc
