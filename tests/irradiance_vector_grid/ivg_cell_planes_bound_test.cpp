// The bound on the grid's cell-plane classification (host/methods/grid/ivg_cell_planes.h):
// coincident copies of a triangle cost no more than the triangle, distinct triangles that overlap
// in many cells stop at the budget of triangle-box tests and leave the cells they reach without a
// plane, and ordinary meshes (with or without copies) classify exactly as a brute-force reference
// of the classification's rules (every triangle against every cell).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <utility>
#include <vector>

#include "methods/grid/ivg_cell_planes.h"
#include "methods/grid/triangle_box_overlap.h"
#include "test_support.h"

namespace rc {
namespace {

// A grid of n x n x n cells over the box [lower, upper].
shared::IvgParams grid_over(glm::vec3 lower, glm::vec3 upper, int n) {
    shared::IvgParams p{};
    const glm::vec3 cell = (upper - lower) / static_cast<float>(n);
    p.origin = {lower.x, lower.y, lower.z, 0.0f};
    p.cell = {cell.x, cell.y, cell.z, 0.0f};
    p.cells = {n, n, n, 0};
    return p;
}

// Cell (x, y, z) of `p` grown by `grow`, its corners as the kernel computes them (in float).
void grown_cell(const shared::IvgParams& p, int x, int y, int z, double grow, glm::dvec3* lower,
                glm::dvec3* upper) {
    const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
    const int at[3] = {x, y, z};
    for (int axis = 0; axis < 3; ++axis) {
        (*lower)[axis] = double(origin[axis] + float(at[axis]) * cell[axis]) - grow;
        (*upper)[axis] = double(origin[axis] + float(at[axis] + 1) * cell[axis]) + grow;
    }
}

void add_triangle(TriangleMesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const auto first = static_cast<unsigned>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.triangles.emplace_back(first, first + 1, first + 2);
}

// `count` copies of one large triangle across the unit cube's diagonal, each with its own
// vertices, plus a floor below it (two triangles).
TriangleMesh coincident_triangles(size_t count) {
    TriangleMesh mesh;
    add_triangle(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 1});
    add_triangle(mesh, {0, 0, 0}, {1, 1, 1}, {0, 1, 1});
    for (size_t i = 0; i < count; ++i) {
        add_triangle(mesh, {0.05f, 0.1f, 0.0f}, {0.95f, 0.2f, 0.1f}, {0.5f, 0.9f, 1.0f});
    }
    return mesh;
}

// `count` distinct large triangles: the triangle above, each shifted by a little more along x.
TriangleMesh near_coincident_triangles(size_t count) {
    TriangleMesh mesh;
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 shift(1e-6f * static_cast<float>(i), 0.0f, 0.0f);
        add_triangle(mesh, glm::vec3(0.05f, 0.1f, 0.0f) + shift,
                     glm::vec3(0.95f, 0.2f, 0.1f) + shift, glm::vec3(0.5f, 0.9f, 1.0f) + shift);
    }
    return mesh;
}

// A floor (two triangles) under `count` distinct small triangles near the unit cube's far
// corner, each shifted by a little more along x.
TriangleMesh small_triangles_over_floor(size_t count) {
    TriangleMesh mesh;
    add_triangle(mesh, {0, 0.02f, 0}, {0, 0.02f, 1}, {1, 0.02f, 1});
    add_triangle(mesh, {0, 0.02f, 0}, {1, 0.02f, 1}, {1, 0.02f, 0});
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 shift(1e-6f * static_cast<float>(i), 0.0f, 0.0f);
        add_triangle(mesh, glm::vec3(0.76f, 0.76f, 0.8f) + shift,
                     glm::vec3(0.84f, 0.78f, 0.8f) + shift, glm::vec3(0.8f, 0.84f, 0.76f) + shift);
    }
    return mesh;
}

// Each cell's oriented planes, resolved from the table (a missing one as all zeros), so that two
// classifications compare by what the kernel reads.
std::vector<std::array<float, 8>> resolved(const IvgCellPlanes& c) {
    std::vector<std::array<float, 8>> cells;
    for (const shared::IvgCellPlanes& cell : c.cell_planes) {
        std::array<float, 8> e{};
        const int indices[2] = {cell.first, cell.second};
        for (int k = 0; k < 2; ++k) {
            if (indices[k] >= 0) {
                const shared::IvgPlane& plane = c.planes.at(static_cast<size_t>(indices[k]));
                std::memcpy(&e[4 * k], &plane.equation, 4 * sizeof(float));
            }
        }
        cells.push_back(e);
    }
    return cells;
}

// The classification's rules (ivg_cell_planes.h) by brute force: every triangle against every
// cell grown by twice the cell margin, then, per cell with triangles, the planes of its triangles
// in mesh order (distinct ones, at most eight tried) until two free sides are found.
struct Reference {
    std::vector<std::array<float, 8>> cells;
    size_t empty = 0;
    size_t unsupported = 0;
};

struct ReferenceTriangles {
    std::vector<std::array<glm::dvec3, 3>> vertices;
    std::vector<std::pair<glm::dvec3, double>> planes;  // unit normal (zero: no area), offset
};

// A cell's two oriented planes (zeros where missing) from its triangles `in`; *sides: how many.
std::array<float, 8> reference_cell(const ReferenceTriangles& t, const std::vector<size_t>& in,
                                    double tolerance, int* sides) {
    std::array<float, 8> cell{};
    std::vector<size_t> tried;
    for (size_t i : in) {
        if (*sides == 2 || tried.size() == 8) {
            break;
        }
        const glm::dvec3& normal = t.planes[i].first;  // clang 14 captures no bindings
        const double offset = t.planes[i].second;
        const bool seen = std::any_of(tried.begin(), tried.end(), [&](size_t j) {
            return glm::dot(t.planes[j].first, normal) > 1.0 - 1e-12 &&
                   std::fabs(t.planes[j].second - offset) <= tolerance;
        });
        if (normal == glm::dvec3(0.0) || seen) {
            continue;
        }
        tried.push_back(i);
        // The extremes of the signed distances of all the cell's vertices to the plane.
        double lowest = 0.0;
        double highest = 0.0;
        for (size_t j : in) {
            for (const glm::dvec3& vertex : t.vertices[j]) {
                lowest = std::min(lowest, glm::dot(normal, vertex) - offset);
                highest = std::max(highest, glm::dot(normal, vertex) - offset);
            }
        }
        const bool free[2] = {highest <= tolerance, lowest >= -tolerance};
        for (int side = 0; side < 2 && *sides < 2; ++side) {
            if (free[side]) {
                const double sign = side == 0 ? 1.0 : -1.0;
                const std::array<float, 4> e = {float(sign * normal.x), float(sign * normal.y),
                                                float(sign * normal.z), float(-sign * offset)};
                std::copy(e.begin(), e.end(), cell.begin() + 4 * (*sides)++);
            }
        }
    }
    return cell;
}

Reference reference_classification(const TriangleMesh& mesh, const shared::IvgParams& p) {
    // Step 1: the scale s, the margins and the tolerance, as the classification defines them.
    double s = 0.0;
    for (const glm::vec3& x : mesh.positions) {
        s = std::max({s, std::fabs(double(x.x)), std::fabs(double(x.y)), std::fabs(double(x.z))});
    }
    const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
    const int cells[3] = {p.cells.x, p.cells.y, p.cells.z};
    for (int axis = 0; axis < 3; ++axis) {
        s = std::max({s, std::fabs(double(origin[axis])),
                      std::fabs(double(origin[axis]) + double(cells[axis]) * cell[axis])});
    }
    const double grow = 2.0 * static_cast<double>(static_cast<float>(s / 4096.0));
    const double tolerance = s / 4194304.0;
    // Step 2: each triangle's vertices and plane.
    ReferenceTriangles t;
    for (const glm::uvec3& index : mesh.triangles) {
        const std::array<glm::dvec3, 3> v = {glm::dvec3(mesh.positions[index.x]),
                                             glm::dvec3(mesh.positions[index.y]),
                                             glm::dvec3(mesh.positions[index.z])};
        const glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
        const double length = glm::length(n);
        const glm::dvec3 unit = length > 0.0 ? n / length : glm::dvec3(0.0);
        t.vertices.push_back(v);
        t.planes.emplace_back(unit, length > 0.0 ? glm::dot(unit, v[0]) : 0.0);
    }
    // Step 3: per cell, the triangles overlapping it, then its planes.
    Reference r;
    for (int z = 0; z < p.cells.z; ++z) {
        for (int y = 0; y < p.cells.y; ++y) {
            for (int x = 0; x < p.cells.x; ++x) {
                glm::dvec3 lower;
                glm::dvec3 upper;
                grown_cell(p, x, y, z, grow, &lower, &upper);
                std::vector<size_t> in;
                for (size_t i = 0; i < t.vertices.size(); ++i) {
                    const auto& v = t.vertices[i];
                    if (triangle_overlaps_box(v[0], v[1], v[2], lower, upper)) {
                        in.push_back(i);
                    }
                }
                int sides = 0;
                r.cells.push_back(reference_cell(t, in, tolerance, &sides));
                r.empty += in.empty() ? 1 : 0;
                r.unsupported += !in.empty() && sides == 0 ? 1 : 0;
            }
        }
    }
    return r;
}

// A small scene of ordinary meshes: the Cornell box.
TriangleMesh cornell_mesh() { return test::load_cornell_box().mesh; }

// A UV sphere (rings x segments quads, the poles' triangles degenerate) inside a box of six
// faces, both around the origin.
TriangleMesh sphere_in_box() {
    TriangleMesh mesh;
    const int rings = 8;
    const int segments = 12;
    auto point = [&](int ring, int segment) {
        const double theta = 3.14159265358979 * ring / rings;
        const double phi = 2.0 * 3.14159265358979 * segment / segments;
        return glm::vec3(0.6 * std::sin(theta) * std::cos(phi), 0.6 * std::cos(theta),
                         0.6 * std::sin(theta) * std::sin(phi));
    };
    for (int ring = 0; ring < rings; ++ring) {
        for (int segment = 0; segment < segments; ++segment) {
            const glm::vec3 a = point(ring, segment);
            const glm::vec3 b = point(ring + 1, segment);
            const glm::vec3 c = point(ring + 1, segment + 1);
            const glm::vec3 d = point(ring, segment + 1);
            add_triangle(mesh, a, b, c);
            add_triangle(mesh, a, c, d);
        }
    }
    for (int axis = 0; axis < 3; ++axis) {
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 corner[4];
            for (int k = 0; k < 4; ++k) {
                corner[k][axis] = side;
                corner[k][(axis + 1) % 3] = (k == 1 || k == 2) ? 1.0f : -1.0f;
                corner[k][(axis + 2) % 3] = (k >= 2) ? 1.0f : -1.0f;
            }
            add_triangle(mesh, corner[0], corner[1], corner[2]);
            add_triangle(mesh, corner[0], corner[2], corner[3]);
        }
    }
    return mesh;
}

// `mesh` with copies of some of its triangles inserted among them: each third triangle twice
// more (sharing its indices), each fifth once more with vertices of its own.
TriangleMesh with_copies(const TriangleMesh& mesh) {
    TriangleMesh copied;
    copied.positions = mesh.positions;
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3 t = mesh.triangles[i];
        copied.triangles.push_back(t);
        if (i % 3 == 0) {
            copied.triangles.insert(copied.triangles.end(), {t, t});
        }
        if (i % 5 == 0) {
            add_triangle(copied, mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]);
        }
    }
    return copied;
}

void expect_as_reference(const TriangleMesh& mesh, const shared::IvgParams& p) {
    const IvgCellPlanes c = classify_cell_planes(mesh, p);
    const Reference r = reference_classification(mesh, p);
    EXPECT_EQ(c.skipped_triangles, 0u);
    EXPECT_EQ(c.empty_cells, r.empty);
    EXPECT_EQ(c.unsupported_cells, r.unsupported);
    const auto cells = resolved(c);
    ASSERT_EQ(cells.size(), r.cells.size());
    size_t different = 0;
    for (size_t k = 0; k < cells.size(); ++k) {
        different += std::memcmp(cells[k].data(), r.cells[k].data(), sizeof cells[k]) != 0;
    }
    EXPECT_EQ(different, 0u);
    EXPECT_LT(c.empty_cells + c.unsupported_cells, cells.size());  // some cells have planes
}

TEST(IvgCellPlanesBound, OrdinaryMeshesClassifyAsTheReference) {
    const TriangleMesh cornell = cornell_mesh();
    const shared::IvgParams cornell_grid = grid_over({-1, -1, -1}, {560, 550, 560}, 12);
    expect_as_reference(cornell, cornell_grid);
    expect_as_reference(with_copies(cornell), cornell_grid);
    const TriangleMesh box = sphere_in_box();
    const shared::IvgParams box_grid =
        grid_over({-1.01f, -1.01f, -1.01f}, {1.01f, 1.01f, 1.01f}, 10);
    expect_as_reference(box, box_grid);
    expect_as_reference(with_copies(box), box_grid);
    // Copies change nothing: the planes table too is the same.
    const IvgCellPlanes once = classify_cell_planes(box, box_grid);
    const IvgCellPlanes copied = classify_cell_planes(with_copies(box), box_grid);
    EXPECT_GT(copied.copied_triangles, 0u);
    EXPECT_EQ(once.planes.size(), copied.planes.size());
    EXPECT_EQ(resolved(once), resolved(copied));
}

TEST(IvgCellPlanesBound, CoincidentCopiesCostNoMoreThanOneTriangle) {
    const shared::IvgParams p = grid_over({0, 0, 0}, {1, 1, 1}, 16);
    const IvgCellPlanes one = classify_cell_planes(coincident_triangles(1), p);
    const IvgCellPlanes some = classify_cell_planes(coincident_triangles(25000), p);
    const IvgCellPlanes many = classify_cell_planes(coincident_triangles(100000), p);
    // The work does not grow with the copies: the same triangle-box tests as for one triangle.
    EXPECT_GT(one.box_tests, 0u);
    EXPECT_EQ(some.box_tests, one.box_tests);
    EXPECT_EQ(many.box_tests, one.box_tests);
    EXPECT_EQ(some.copied_triangles, 25000u - 1u);
    EXPECT_EQ(many.copied_triangles, 100000u - 1u);
    EXPECT_EQ(many.skipped_triangles, 0u);
    // And the classification is the same.
    EXPECT_EQ(resolved(many), resolved(one));
    EXPECT_EQ(many.planes.size(), one.planes.size());
    EXPECT_EQ(many.empty_cells, one.empty_cells);
    EXPECT_EQ(many.unsupported_cells, one.unsupported_cells);
}

// Every cell with a plane has every triangle of the mesh that overlaps it on the plane or behind
// it (within the float rounding of the stored equation): what the kernel relies on.
void expect_planes_hold(const TriangleMesh& mesh, const shared::IvgParams& p,
                        const IvgCellPlanes& c) {
    const double grow = 2.0 * c.cell_margin;
    size_t violations = 0;
    for (int z = 0; z < p.cells.z; ++z) {
        for (int y = 0; y < p.cells.y; ++y) {
            for (int x = 0; x < p.cells.x; ++x) {
                const size_t k = (static_cast<size_t>(z) * p.cells.y + y) * p.cells.x + x;
                const shared::IvgCellPlanes& cell = c.cell_planes[k];
                if (cell.first < 0) {
                    continue;
                }
                glm::dvec3 lower;
                glm::dvec3 upper;
                grown_cell(p, x, y, z, grow, &lower, &upper);
                for (const glm::uvec3& t : mesh.triangles) {
                    const glm::dvec3 v[3] = {glm::dvec3(mesh.positions[t.x]),
                                             glm::dvec3(mesh.positions[t.y]),
                                             glm::dvec3(mesh.positions[t.z])};
                    if (!triangle_overlaps_box(v[0], v[1], v[2], lower, upper)) {
                        continue;
                    }
                    for (int index : {cell.first, cell.second}) {
                        if (index < 0) {
                            continue;
                        }
                        const auto& e = c.planes[static_cast<size_t>(index)].equation;
                        for (const glm::dvec3& vertex : v) {
                            const double d = e.x * vertex.x + e.y * vertex.y + e.z * vertex.z + e.w;
                            violations += d > 1e-5 ? 1 : 0;
                        }
                    }
                }
            }
        }
    }
    EXPECT_EQ(violations, 0u);
}

TEST(IvgCellPlanesBound, DistinctOverlappingTrianglesStopAtTheBudget) {
    const shared::IvgParams p = grid_over({0, 0, 0}, {1, 1, 1}, 8);
    const size_t cells = 8 * 8 * 8;
    const size_t per_element = 16;
    const IvgCellPlanes some =
        classify_cell_planes(near_coincident_triangles(25000), p, per_element);
    const IvgCellPlanes many =
        classify_cell_planes(near_coincident_triangles(100000), p, per_element);
    // The tests stay within the budget, which grows linearly: per distinct triangle and cell.
    EXPECT_LE(some.box_tests, per_element * (25000 + cells));
    EXPECT_LE(many.box_tests, per_element * (100000 + cells));
    EXPECT_GT(many.skipped_triangles, 0u);
    EXPECT_EQ(many.copied_triangles, 0u);
    // The cells the skipped triangles reach have no plane; no cell claims a plane that a triangle
    // it overlaps lies in front of.
    EXPECT_EQ(many.empty_cells + many.unsupported_cells, many.cell_planes.size());
    // With a budget of one test per triangle and cell, the floor and some small triangles are
    // classified, the other small triangles' cells left without a plane.
    const TriangleMesh few = small_triangles_over_floor(200);
    const IvgCellPlanes bounded = classify_cell_planes(few, p, 1);
    EXPECT_GT(bounded.skipped_triangles, 0u);
    EXPECT_LT(bounded.skipped_triangles, 200u);
    EXPECT_LT(bounded.empty_cells + bounded.unsupported_cells, bounded.cell_planes.size());
    EXPECT_EQ(bounded.cell_planes[(6 * 8 + 6) * 8 + 6].first, -1);
    expect_planes_hold(few, p, bounded);
    // Under the default budget the same triangles are all classified, and the planes still hold.
    const IvgCellPlanes unbounded = classify_cell_planes(few, p);
    EXPECT_EQ(unbounded.skipped_triangles, 0u);
    EXPECT_LT(unbounded.empty_cells + unbounded.unsupported_cells, unbounded.cell_planes.size());
    expect_planes_hold(few, p, unbounded);
}

}  // namespace
}  // namespace rc
