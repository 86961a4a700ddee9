// The irradiance vector grid's kernels (kernels/irradiance_vector_grid/ivg_deposit.h,
// ivg_lookup.h): photon deposition against a brute-force host reference and against the report's
// rules (§3.3), normalisation against known irradiance vectors (a parallel beam, an isotropic
// field), and the lookup's interpolation and blending.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "methods/grid/irradiance_vector_grid.h"
#include "scene/device_scene.h"
#include "test_support.h"

namespace rc {
namespace {

// A grid object on the Cornell box's device scene (the tests set their own params).
struct GridFixture {
    GridFixture() : device(test::load_cornell_box()), grid(device.frame()) {}
    test::DeviceFrame device;
    IrradianceVectorGrid grid;
};

GridFixture& fixture() {
    static GridFixture* f = new GridFixture();
    return *f;
}

shared::IvgParams unit_grid(int n, float units) {
    shared::IvgParams p{};
    p.origin = {0.0f, 0.0f, 0.0f, 0.0f};
    p.fixed_point_scale = units;
    p.cell = {1.0f, 1.0f, 1.0f, 0.0f};
    p.min_cosine = 0.1f;
    p.cells = {n, n, n, 0};
    p.vertex_count = (n + 1) * (n + 1) * (n + 1);
    p.photon_count = 1;
    return p;
}

size_t slot(const shared::IvgParams& p, int i, int j, int k, int direction) {
    const size_t v = (static_cast<size_t>(k) * (p.cells.y + 1) + j) * (p.cells.x + 1) + i;
    return (v * 6 + direction) * 9;
}

// The reference deposition: every plane of every axis tested against the segment in double
// precision (no walk); the fixed-point amount is the kernel's float formula, so the sums must
// agree exactly. This one pins the kernel's own conventions (ties, segment ends, the grazing
// clamp) bit for bit; the independent oracle, from the report's text, is
// NormalisedGridFollowsTheReportsFaceCrossingRules below.
std::vector<int64_t> reference_deposit(const shared::IvgParams& p,
                                       const std::vector<PhotonSegment>& segments) {
    std::vector<int64_t> sums(static_cast<size_t>(p.vertex_count) * RC_IVG_VALUES_PER_VERTEX, 0);
    const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
    const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
    const int cells[3] = {p.cells.x, p.cells.y, p.cells.z};
    for (const PhotonSegment& s : segments) {
        const float d[3] = {s.to.x - s.from.x, s.to.y - s.from.y, s.to.z - s.from.z};
        const double length =
            std::sqrt(double(d[0]) * d[0] + double(d[1]) * d[1] + double(d[2]) * d[2]);
        const float flux[3] = {s.flux.x, s.flux.y, s.flux.z};
        for (int axis = 0; axis < 3; ++axis) {
            if (d[axis] == 0.0f) {
                continue;
            }
            for (int n = 0; n <= cells[axis]; ++n) {
                const double plane = double(origin[axis]) + double(n) * cell[axis];
                const double s_n = (plane - s.from[axis]) / d[axis];
                const double along = s_n * std::fabs(double(d[axis]));
                const double tolerance = 1e-4 * cell[axis];
                if (!(along > tolerance && along <= std::fabs(double(d[axis])) + tolerance)) {
                    continue;
                }
                int index[3];
                bool inside = true;
                for (int other = 0; other < 3; ++other) {
                    if (other == axis) {
                        index[other] = n;
                        continue;
                    }
                    const double x = s.from[other] + s_n * d[other];
                    const double g = (x - origin[other]) / cell[other];
                    // Rounding half up is defined, but float and double may fall on either side
                    // of a tie: the segments must keep clear of them.
                    EXPECT_GT(std::fabs(g - std::floor(g) - 0.5), 1e-4)
                        << "a test segment crosses midway between vertices";
                    inside = inside && g >= -1e-4 && g <= cells[other] + 1e-4;
                    index[other] =
                        std::clamp(static_cast<int>(std::floor(g + 0.5)), 0, cells[other]);
                }
                if (!inside) {
                    continue;
                }
                const int direction = 2 * axis + (d[axis] < 0.0f ? 0 : 1);
                const float denominator =
                    std::max(std::fabs(d[axis]), p.min_cosine * static_cast<float>(length));
                const size_t base = slot(p, index[0], index[1], index[2], direction);
                for (int c = 0; c < 3; ++c) {
                    for (int k = 0; k < 3; ++k) {
                        const float value = flux[c] * -d[k] / denominator * p.fixed_point_scale;
                        sums[base + 3 * c + k] += static_cast<int64_t>(std::rint(value));
                    }
                }
            }
        }
    }
    return sums;
}

TEST(IvgDeposit, MatchesBruteForceIncludingEdgesCornersAndEnds) {
    const shared::IvgParams p = unit_grid(4, 1024.0f);
    const glm::vec3 flux(1.0f, 0.5f, 0.25f);
    const std::vector<PhotonSegment> segments = {
        {{0.25f, 1.25f, 2.75f}, {3.75f, 1.25f, 2.75f}, flux},           // along +x: planes 1, 2, 3
        {{0.5f, 0.5f, 0.5f}, {3.5f, 3.5f, 3.5f}, flux},                 // through three vertices
        {{0.5f, 0.5f, 1.25f}, {2.5f, 2.5f, 1.25f}, flux},               // through two edges
        {{1.75f, 3.5f, 0.25f}, {1.75f, 0.0f, 0.25f}, flux},             // ends on the y = 0 face
        {{2.0f, 0.75f, 0.25f}, {3.5f, 0.75f, 0.25f}, flux},             // starts on the x = 2 plane
        {{3.5f, 2.25f, 1.75f}, {6.5f, 2.25f, 1.75f}, flux},             // leaves through x = 4
        {{-1.0f, 5.0f, 1.0f}, {5.0f, 5.0f, 1.0f}, flux},                // outside the grid
        {{0.3f, 0.7f, 0.1f}, {3.9f, 2.2f, 3.4f}, {2.0f, 1.0f, 3.0f}},   // oblique
        {{3.9f, 0.2f, 3.7f}, {0.35f, 3.1f, 0.6f}, {0.7f, 0.7f, 0.7f}},  // oblique, backwards
    };
    const std::vector<int64_t> device = fixture().grid.deposit(p, segments);
    const std::vector<int64_t> expected = reference_deposit(p, segments);
    ASSERT_EQ(device.size(), expected.size());
    size_t nonzero = 0;
    for (size_t i = 0; i < expected.size(); ++i) {
        ASSERT_EQ(device[i], expected[i])
            << "value " << i << " (vertex " << i / RC_IVG_VALUES_PER_VERTEX << ", direction "
            << i / 9 % 6 << ")";
        nonzero += expected[i] != 0;
    }
    EXPECT_GT(nonzero, 100u);
    // Hand-checked entries: the +x segment crosses x = 1, 2, 3 at y = 1.25 -> j = 1, z = 2.75 ->
    // k = 3, into the -x vector (light from the -x side): -flux.r * 1024 in the x component.
    for (int i = 1; i <= 3; ++i) {
        EXPECT_EQ(device[slot(p, i, 1, 3, 1) + 0], -1024) << i;
    }
    // The segment ending on y = 0 reaches the face's vertex (2, 0, 0); the one starting on x = 2
    // does not deposit at x = 2 but does at x = 3.
    EXPECT_NE(device[slot(p, 2, 0, 0, 2) + 1], 0);
    EXPECT_EQ(device[slot(p, 2, 1, 0, 1)], 0);
    EXPECT_EQ(device[slot(p, 3, 1, 0, 1)], -1024);
}

// The deposited and normalised grid against the report's rules (RR-6983 §3.3, DESIGN.md §6.3),
// written from the text and not from the kernel: every time a photon traverses a voxel face, its
// contribution goes to the irradiance vector of the vertex whose face cell (the rectangle centred
// on the vertex, one voxel face in size, cut at the grid's boundary) contains the crossing, for
// the side the photon comes from (a photon travelling towards -x lights the +x vector);
// I = sum phi omega / (N A), N the photon count and A the face cell's area (the voxel face's,
// halved on a grid face, quartered on an edge). One documented change to the report (the kernel's
// header and docs/irradiance-vector-grid.md): a crossing at angle theta to the face normal counts
// omega / |cos theta|, which makes the sum Arvo's irradiance vector (photons cross a face in
// proportion to |cos theta|). Crossings are counted strictly after a segment's start and up to
// its end. The test's segments keep every |cos theta| >= 0.19, above the grazing clamp, and every
// crossing clear of face-cell and grid borders, so no rounding convention decides anything.
struct ReportGrid {
    glm::dvec3 origin{-1.0, 0.5, 2.0};
    glm::dvec3 cell{1.0, 0.5, 2.0};
    glm::ivec3 cells{3, 2, 2};
    int photons = 4;
};

// The one place that fills the kernel's parameter block for this grid.
shared::IvgParams report_grid_params(const ReportGrid& g, float units) {
    shared::IvgParams p{};
    p.origin = {float(g.origin.x), float(g.origin.y), float(g.origin.z), 0.0f};
    p.fixed_point_scale = units;
    p.cell = {float(g.cell.x), float(g.cell.y), float(g.cell.z), 0.0f};
    p.min_cosine = 0.1f;
    p.cells = {g.cells.x, g.cells.y, g.cells.z, 0};
    p.vertex_count = (g.cells.x + 1) * (g.cells.y + 1) * (g.cells.z + 1);
    p.photon_count = static_cast<unsigned>(g.photons);
    return p;
}

// The vertex index along axis b whose face-cell interval contains coordinate x, or -1 outside the
// grid; checks that x is not within `clear` (in cells) of an interval's end.
int face_cell_index(const ReportGrid& g, int b, double x, double clear) {
    const double lower = g.origin[b];
    const double upper = g.origin[b] + g.cells[b] * g.cell[b];
    for (int k = 0; k <= g.cells[b]; ++k) {
        const double centre = g.origin[b] + k * g.cell[b];
        const double from = std::max(lower, centre - 0.5 * g.cell[b]);
        const double to = std::min(upper, centre + 0.5 * g.cell[b]);
        EXPECT_GT(std::min(std::fabs(x - from), std::fabs(x - to)), clear * g.cell[b])
            << "a test crossing lies on a face cell's border";
        if (x > from && x < to) {
            return k;
        }
    }
    return -1;
}

// Expected normalised vectors: [vertex][direction][channel] as a dvec3, vertices in (i, j, k)
// order with i fastest, directions +x, -x, +y, -y, +z, -z.
using ExpectedGrid = std::vector<std::array<std::array<glm::dvec3, 3>, 6>>;

ExpectedGrid report_reference(const ReportGrid& g, const std::vector<PhotonSegment>& segments,
                              int* crossings) {
    const glm::ivec3 n = g.cells + 1;
    ExpectedGrid grid(static_cast<size_t>(n.x) * n.y * n.z);
    for (const PhotonSegment& s : segments) {
        const glm::dvec3 a(s.from), w = glm::dvec3(s.to) - a;
        const glm::dvec3 omega = -glm::normalize(w);  // towards where the light comes from
        for (int axis = 0; axis < 3; ++axis) {
            if (w[axis] == 0.0) {
                continue;
            }
            const double cosine = std::fabs(omega[axis]);
            EXPECT_GT(cosine, 0.19) << "a test segment grazes the faces";
            // The side the photon comes from: travelling towards +axis it lights the -axis vector.
            const int direction = 2 * axis + (w[axis] > 0.0 ? 1 : 0);
            for (int m = 0; m <= g.cells[axis]; ++m) {
                const double t = (g.origin[axis] + m * g.cell[axis] - a[axis]) / w[axis];
                if (!(t > 0.0 && t <= 1.0)) {
                    continue;
                }
                const glm::dvec3 x = a + t * w;
                glm::ivec3 vertex;
                bool inside = true;
                for (int b = 0; b < 3; ++b) {
                    vertex[b] = b == axis ? m : face_cell_index(g, b, x[b], 1e-3);
                    inside = inside && vertex[b] >= 0;
                }
                if (!inside) {
                    continue;
                }
                ++*crossings;
                // Face cell area: the voxel face, halved per other axis on the boundary.
                double area = 1.0;
                for (int b = 0; b < 3; ++b) {
                    if (b != axis) {
                        const bool border = vertex[b] == 0 || vertex[b] == g.cells[b];
                        area *= g.cell[b] * (border ? 0.5 : 1.0);
                    }
                }
                const size_t v = (static_cast<size_t>(vertex.z) * n.y + vertex.y) * n.x + vertex.x;
                for (int c = 0; c < 3; ++c) {
                    grid[v][direction][c] +=
                        double(s.flux[c]) * omega / cosine / (g.photons * area);
                }
            }
        }
    }
    return grid;
}

TEST(IvgDeposit, NormalisedGridFollowsTheReportsFaceCrossingRules) {
    const ReportGrid g;  // x in [-1, 2], y in [0.5, 1.5], z in [2, 6]
    const std::vector<PhotonSegment> segments = {
        // Towards -x along the grid's y = 0.6, z = 2.3 corner edge, past both x faces.
        {{2.5f, 0.6f, 2.3f}, {-1.5f, 0.6f, 2.3f}, {1.0f, 2.0f, 3.0f}},
        // Up and along +z, leaving through the y = 1.5 face before the z = 4 plane.
        {{0.3f, 1.2f, 3.0f}, {0.3f, 2.5f, 5.5f}, {0.5f, 0.5f, 0.5f}},
        // Oblique through the interior, and back the other way.
        {{-0.8f, 0.7f, 2.6f}, {1.6f, 1.45f, 5.2f}, {2.0f, 1.0f, 0.25f}},
        {{1.7f, 1.4f, 5.7f}, {-0.9f, 0.55f, 2.2f}, {0.75f, 1.5f, 1.0f}},
        // Ends inside a voxel, short of the next plane.
        {{0.1f, 0.8f, 4.6f}, {1.4f, 1.3f, 3.3f}, {1.0f, 1.0f, 1.0f}},
    };
    const float units = 1048576.0f;  // 2^20 fixed-point steps per unit of flux
    const shared::IvgParams p = report_grid_params(g, units);
    int crossings = 0;
    const ExpectedGrid expected = report_reference(g, segments, &crossings);
    GridFixture& f = fixture();
    const std::vector<float> device = f.grid.normalize(p, f.grid.deposit(p, segments));
    ASSERT_EQ(device.size(), expected.size() * 54);
    // Fixed point: each crossing's amount (at most |flux| / 0.19 ~ 16 units of flux) is rounded
    // to a step of 1/units, after float rounding (2^-24 relative, ~1 step at 2^20 units): under
    // 2 steps per crossing, then divided by N A >= 4 * 0.125. Bounded by 4 steps per crossing of
    // the whole test, plus float rounding of the normalised value.
    const double tolerance = crossings * 4.0 / units + 1e-6;
    size_t nonzero = 0;
    for (size_t v = 0; v < expected.size(); ++v) {
        for (int direction = 0; direction < 6; ++direction) {
            for (int c = 0; c < 3; ++c) {
                for (int k = 0; k < 3; ++k) {
                    const double want = expected[v][direction][c][k];
                    const float got = device[(v * 6 + direction) * 9 + 3 * c + k];
                    EXPECT_NEAR(got, want, tolerance * std::max(1.0, std::fabs(want)))
                        << "vertex " << v << ", direction " << direction << ", channel " << c
                        << ", component " << k;
                    nonzero += want != 0.0 ? 1 : 0;
                }
            }
        }
    }
    EXPECT_GT(crossings, 15);
    EXPECT_GT(nonzero, 60u);
    // By hand: the first photon crosses x = 2, 1, 0, -1 at (y, z) = (0.6, 2.3), in the face cells
    // of vertices (i, 0, 0), corners of the y and z extents: area 0.5 * 2 / 4 = 0.25. Travelling
    // towards -x with |cos| = 1 it adds flux * (+1, 0, 0) to the +x vectors; / (4 photons * 0.25).
    for (int i = 0; i <= 3; ++i) {
        const float* plus_x = &device[(static_cast<size_t>(i) * 6 + 0) * 9];
        EXPECT_NEAR(plus_x[0], 1.0, 1e-5) << i;  // red, x
        EXPECT_NEAR(plus_x[3], 2.0, 1e-5) << i;  // green, x
        EXPECT_NEAR(plus_x[6], 3.0, 1e-5) << i;  // blue, x
        EXPECT_EQ(plus_x[1], 0.0f) << i;
    }
}

// Photon segments of a parallel beam crossing the whole grid, stratified over a square launch
// area (one jittered photon per stratum): incident direction `toward_light`, irradiance
// `irradiance` on a plane perpendicular to the beam.
std::vector<PhotonSegment> parallel_beam(glm::vec3 toward_light, float irradiance, int strata,
                                         float* flux_per_photon) {
    const glm::vec3 travel = -glm::normalize(toward_light);
    const glm::vec3 centre(2.0f);
    const float half = 6.0f;  // the launch square covers the grid's shadow
    const glm::vec3 t = glm::normalize(glm::cross(travel, glm::vec3(0.3f, 0.5f, 0.9f)));
    const glm::vec3 b = glm::cross(travel, t);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float side = 2.0f * half / static_cast<float>(strata);
    *flux_per_photon = irradiance * side * side;
    std::vector<PhotonSegment> segments;
    for (int i = 0; i < strata; ++i) {
        for (int j = 0; j < strata; ++j) {
            const float a = -half + (static_cast<float>(i) + u(rng)) * side;
            const float c = -half + (static_cast<float>(j) + u(rng)) * side;
            const glm::vec3 start = centre - 10.0f * travel + a * t + c * b;
            segments.push_back({start, start + 20.0f * travel, glm::vec3(*flux_per_photon)});
        }
    }
    return segments;
}

TEST(IvgNormalize, ParallelBeamGivesItsIrradianceVectorAtEveryVertex) {
    const glm::vec3 toward_light = glm::normalize(glm::vec3(0.45f, 0.8f, -0.4f));
    const float irradiance = 3.0f;
    float flux = 0.0f;
    const std::vector<PhotonSegment> beam = parallel_beam(toward_light, irradiance, 600, &flux);
    shared::IvgParams p = unit_grid(4, 1e6f / flux);
    p.photon_count = 1;  // the flux per photon already includes the division by the count
    GridFixture& f = fixture();
    const std::vector<float> values = f.grid.normalize(p, f.grid.deposit(p, beam));
    const int directions[3] = {0, 2, 5};  // +x, +y, -z: the sides the light comes from
    double worst = 0.0;
    for (int k = 0; k <= 4; ++k) {
        for (int j = 0; j <= 4; ++j) {
            for (int i = 0; i <= 4; ++i) {
                for (int direction : directions) {
                    const float* v = &values[slot(p, i, j, k, direction)];
                    for (int c = 0; c < 3; ++c) {
                        for (int a = 0; a < 3; ++a) {
                            const double expected = irradiance * toward_light[a];
                            worst = std::max(worst, std::fabs(v[3 * c + a] - expected));
                        }
                    }
                }
                // The other sides receive nothing.
                for (int direction : {1, 3, 4}) {
                    EXPECT_EQ(values[slot(p, i, j, k, direction)], 0.0f);
                }
            }
        }
    }
    // 2500 stratified photons per unit area: under 2% per face cell, quarter cells on the
    // grid's edges included.
    EXPECT_LT(worst, 0.03 * irradiance) << "largest deviation from E w";
}

TEST(IvgNormalize, IsotropicFieldGivesOppositeVectorsOfEqualLength) {
    // Uniform random lines through a sphere of radius R around the grid: an isotropic field of
    // radiance L = N flux / (4 pi * pi R^2); each side's vector is pi L along its axis.
    const int count = 300000;
    const float radius = 4.0f;
    const float flux = 1.0f;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<PhotonSegment> segments;
    const glm::vec3 centre(2.0f);
    for (int i = 0; i < count; ++i) {
        const float z = 1.0f - 2.0f * u(rng);
        const float phi = 6.2831853f * u(rng);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const glm::vec3 w(r * std::cos(phi), r * std::sin(phi), z);
        const glm::vec3 t = glm::normalize(
            glm::cross(w, std::fabs(w.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
        const glm::vec3 b = glm::cross(w, t);
        const float rho = radius * std::sqrt(u(rng));
        const float angle = 6.2831853f * u(rng);
        const glm::vec3 start =
            centre + rho * (std::cos(angle) * t + std::sin(angle) * b) - 2.0f * radius * w;
        segments.push_back({start, start + 4.0f * radius * w, glm::vec3(flux)});
    }
    shared::IvgParams p = unit_grid(4, 1e6f);
    GridFixture& f = fixture();
    const std::vector<float> values = f.grid.normalize(p, f.grid.deposit(p, segments));
    const double pi = 3.14159265358979;
    const double radiance = count * flux / (4.0 * pi * pi * radius * radius);
    double sum_plus = 0.0;
    double sum_minus = 0.0;
    int vertices = 0;
    for (int k = 1; k <= 3; ++k) {
        for (int j = 1; j <= 3; ++j) {
            for (int i = 1; i <= 3; ++i) {
                for (int axis = 0; axis < 3; ++axis) {
                    const float* plus = &values[slot(p, i, j, k, 2 * axis)];
                    const float* minus = &values[slot(p, i, j, k, 2 * axis + 1)];
                    sum_plus += plus[axis];
                    sum_minus += minus[axis];
                    // Transverse components vanish up to noise.
                    for (int a = 0; a < 3; ++a) {
                        if (a != axis) {
                            EXPECT_LT(std::fabs(plus[a]), 0.15 * pi * radiance);
                        }
                    }
                }
                ++vertices;
            }
        }
    }
    const double mean_plus = sum_plus / (3.0 * vertices);
    const double mean_minus = sum_minus / (3.0 * vertices);
    EXPECT_NEAR(mean_plus, -mean_minus, 0.02 * mean_plus);
    // The clamp of grazing crossings (|cos| >= 0.1) removes about 0.3% of the length.
    EXPECT_NEAR(mean_plus, pi * radiance, 0.03 * pi * radiance);
}

// A grid whose vectors are given by a function of the vertex's position and direction.
std::vector<float> field(const shared::IvgParams& p,
                         const std::function<glm::vec3(glm::vec3, int direction, int c)>& f) {
    std::vector<float> values(static_cast<size_t>(p.vertex_count) * RC_IVG_VALUES_PER_VERTEX);
    for (int k = 0; k <= p.cells.z; ++k) {
        for (int j = 0; j <= p.cells.y; ++j) {
            for (int i = 0; i <= p.cells.x; ++i) {
                const glm::vec3 x(p.origin.x + i * p.cell.x, p.origin.y + j * p.cell.y,
                                  p.origin.z + k * p.cell.z);
                for (int direction = 0; direction < 6; ++direction) {
                    for (int c = 0; c < 3; ++c) {
                        const glm::vec3 v = f(x, direction, c);
                        float* out = &values[slot(p, i, j, k, direction) + 3 * c];
                        out[0] = v.x;
                        out[1] = v.y;
                        out[2] = v.z;
                    }
                }
            }
        }
    }
    return values;
}

shared::IvgParams lookup_grid(int interpolation, bool compressed) {
    shared::IvgParams p{};
    p.origin = {-1.0f, 0.5f, 2.0f, 0.0f};
    p.fixed_point_scale = 1.0f;
    p.cell = {0.5f, 0.25f, 1.0f, 0.0f};
    p.min_cosine = 0.1f;
    p.cells = {6, 5, 4, 0};
    p.vertex_count = 7 * 6 * 5;
    p.interpolation = interpolation;
    p.compressed = compressed ? 1 : 0;
    return p;
}

std::vector<glm::vec3> random_points(const shared::IvgParams& p, int count, float margin) {
    std::mt19937 rng(3);
    std::vector<glm::vec3> points;
    for (int n = 0; n < count; ++n) {
        glm::vec3 x;
        const int cells[3] = {p.cells.x, p.cells.y, p.cells.z};
        const float origin[3] = {p.origin.x, p.origin.y, p.origin.z};
        const float cell[3] = {p.cell.x, p.cell.y, p.cell.z};
        for (int a = 0; a < 3; ++a) {
            std::uniform_real_distribution<float> u(margin, cells[a] - margin);
            x[a] = origin[a] + u(rng) * cell[a];
        }
        points.push_back(x);
    }
    return points;
}

// The grid `p` holding `scalar(x, c)` (channel c) along x on its +x side and `elsewhere` on the
// others (not read with n = +x), read with n = +x at 200 random points `margin` cells inside its
// border: each channel within `tolerance` of the field, relatively.
template <class Scalar>
void expect_lookup_reproduces(const shared::IvgParams& p, const Scalar& scalar, glm::vec3 elsewhere,
                              float margin, float tolerance) {
    GridFixture& f = fixture();
    f.grid.set_params(p);
    f.grid.set_values(field(p, [&](glm::vec3 x, int direction, int c) {
        return direction == 0 ? glm::vec3(scalar(x, c), 0.0f, 0.0f) : elsewhere;
    }));
    const std::vector<glm::vec3> points = random_points(p, 200, margin);
    const std::vector<glm::vec3> normals(points.size(), glm::vec3(1.0f, 0.0f, 0.0f));
    const std::vector<glm::vec3> e = f.grid.lookup(points, normals);
    for (size_t q = 0; q < points.size(); ++q) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(e[q][c], scalar(points[q], c), tolerance * scalar(points[q], c)) << q;
        }
    }
}

TEST(IvgLookup, TrilinearReproducesLinearFields) {
    auto linear = [](glm::vec3 x, int c) {
        return 2.0f + 0.3f * x.x - 0.2f * x.y + 0.1f * x.z + 0.5f * static_cast<float>(c);
    };
    expect_lookup_reproduces(lookup_grid(RC_IVG_TRILINEAR, false), linear,
                             glm::vec3(5.0f, 7.0f, 9.0f), 0.0f, 2e-5f);
}

TEST(IvgLookup, TricubicInterpolatesVerticesAndReproducesQuadraticFields) {
    GridFixture& f = fixture();
    const shared::IvgParams p = lookup_grid(RC_IVG_TRICUBIC, false);
    auto quadratic = [](glm::vec3 x, int c) {
        return 3.0f + 0.4f * x.x * x.x - 0.3f * x.y * x.z + 0.2f * x.z * x.z + 0.1f * x.y +
               0.25f * static_cast<float>(c);
    };
    // Away from the border (where the clamped stencil is no longer exact).
    expect_lookup_reproduces(p, quadratic, glm::vec3(1.0f), 1.0f, 1e-4f);
    // At the vertices themselves, any field: a random one.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.5f, 2.0f);
    const std::vector<float> random =
        field(p, [&](glm::vec3, int, int) { return glm::vec3(u(rng), u(rng), u(rng)); });
    f.grid.set_values(random);
    std::vector<glm::vec3> vertices;
    std::vector<float> expected;
    for (int i = 0; i <= p.cells.x; i += 2) {
        for (int j = 0; j <= p.cells.y; j += 2) {
            const int k = 1;
            vertices.emplace_back(p.origin.x + i * p.cell.x, p.origin.y + j * p.cell.y,
                                  p.origin.z + k * p.cell.z);
            expected.push_back(random[slot(p, i, j, k, 0)]);  // red, x component
        }
    }
    const std::vector<glm::vec3> at = f.grid.lookup(
        vertices, std::vector<glm::vec3>(vertices.size(), glm::vec3(1.0f, 0.0f, 0.0f)));
    for (size_t q = 0; q < vertices.size(); ++q) {
        EXPECT_NEAR(at[q].x, std::max(0.0f, expected[q]), 1e-5f) << q;
    }
}

TEST(IvgLookup, BlendsTheSidesTheNormalFacesBySquaredComponents) {
    GridFixture& f = fixture();
    for (bool compressed : {false, true}) {
        const shared::IvgParams p = lookup_grid(RC_IVG_TRILINEAR, compressed);
        f.grid.set_params(p);
        // Side d holds (d + 1) times a fixed direction per side, scaled per channel.
        const glm::vec3 sides[6] = {{1, 0, 0},  {-1, 0, 0}, {0.6f, 0.8f, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0.6f, -0.8f}};
        f.grid.set_values(field(p, [&](glm::vec3, int direction, int c) {
            return sides[direction] * static_cast<float>(direction + 1) * (1.0f + 0.5f * c);
        }));
        // n faces +x, +y, -z: reads sides 0, 2, 5.
        const glm::vec3 n = glm::normalize(glm::vec3(0.5f, 0.6f, -0.3f));
        const std::vector<glm::vec3> e = f.grid.lookup({glm::vec3(0.3f, 1.1f, 3.4f)}, {n});
        for (int c = 0; c < 3; ++c) {
            const float scale = 1.0f + 0.5f * c;
            const glm::vec3 blended = n.x * n.x * sides[0] * 1.0f * scale +
                                      n.y * n.y * sides[2] * 3.0f * scale +
                                      n.z * n.z * sides[5] * 6.0f * scale;
            const float expected = std::max(0.0f, glm::dot(blended, n));
            // Half floats keep about 3 decimal digits.
            EXPECT_NEAR(e[0][c], expected, (compressed ? 2e-3f : 1e-5f) * expected)
                << "channel " << c << (compressed ? " compressed" : "");
        }
    }
}

}  // namespace
}  // namespace rc
