// --decomp-source radiosity (host/methods/decomposition/decomp_radiosity_source.cpp,
// kernels/decomposition/decomp_radiosity_rays.h): the split trees find the split triangle a point
// lies on (against a brute-force search over the split triangles), the cluster rays' split
// triangle is the one a brute-force ray test over every split triangle hits first, and in a
// furnace the iterated radiosity follows the analytic series of its bounces and, with the
// bounces' tail extrapolated, comes close to its sum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <optional>
#include <random>

#include "glossy_scenes.h"  // test::bitwise_equal
#include "image/image.h"
#include "image_options.h"
#include "methods/decomposition/decomposition.h"
#include "methods/decomposition/triangle_split.h"
#include "methods/radiance_source.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/glm_helpers.h"

namespace rc {
namespace {

// Barycentric coordinates (b1, b2) of point x in the plane of triangle t; x lies on t when both
// and 1 - b1 - b2 are at least -tolerance.
bool contains(const shared::NearTriangle& t, const glm::dvec3& x, double tolerance) {
    const glm::dvec3 a(vec3_of(t.v0));
    const glm::dvec3 e1 = glm::dvec3(vec3_of(t.v1)) - a;
    const glm::dvec3 e2 = glm::dvec3(vec3_of(t.v2)) - a;
    const glm::dvec3 d = x - a;
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double p1 = glm::dot(d, e1), p2 = glm::dot(d, e2);
    const double det = d11 * d22 - d12 * d12;
    const double b1 = (d22 * p1 - d12 * p2) / det;
    const double b2 = (d11 * p2 - d12 * p1) / det;
    return b1 >= -tolerance && b2 >= -tolerance && 1.0 - b1 - b2 >= -tolerance;
}

// A mesh of random triangles of very different sizes and shapes.
TriangleMesh random_mesh(int count) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    TriangleMesh mesh;
    for (int i = 0; i < count; ++i) {
        const float scale = i % 3 == 0 ? 0.3f : 1.0f;
        const glm::vec3 base(u(rng), u(rng), u(rng));
        for (int k = 0; k < 3; ++k) {
            mesh.positions.push_back(base + scale * glm::vec3(u(rng), u(rng), u(rng)));
        }
        const uint32_t first = static_cast<uint32_t>(3 * i);
        mesh.triangles.push_back(glm::uvec3(first, first + 1, first + 2));
    }
    return mesh;
}

// The split tree of each scene triangle (split_triangle_of) finds, for random points of it, a
// split triangle that contains the point, the one a brute-force search over all split triangles
// of that scene triangle finds (up to points on a shared edge: then both contain it).
TEST(DecompositionSplitTree, FindsTheSplitTriangleABruteForceSearchFinds) {
    const TriangleMesh mesh = random_mesh(12);
    const float alpha = 0.5f;
    const TriangleSplit split = split_triangle_tree(mesh, alpha, size_t{1} << 20);
    ASSERT_EQ(split.roots.size(), mesh.triangles.size());
    const std::vector<shared::NearTriangle> plain = split_triangles(mesh, alpha, size_t{1} << 20);
    ASSERT_EQ(plain.size(), split.triangles.size());
    EXPECT_EQ(std::memcmp(plain.data(), split.triangles.data(),
                          plain.size() * sizeof(shared::NearTriangle)),
              0);
    // The split triangles of primitive p: the leaves between its root and the next one's.
    std::vector<uint32_t> first(mesh.triangles.size() + 1, 0);
    size_t leaves = 0;
    for (size_t p = 0; p < mesh.triangles.size(); ++p) {
        first[p] = static_cast<uint32_t>(leaves);
        const size_t end = p + 1 < mesh.triangles.size() ? split.roots[p + 1] : split.nodes.size();
        for (size_t n = split.roots[p]; n < end; ++n) {
            leaves += split.nodes[n].triangle >= 0 ? 1 : 0;
        }
    }
    first.back() = static_cast<uint32_t>(leaves);
    ASSERT_EQ(leaves, split.triangles.size());
    ASSERT_GT(leaves, 20 * mesh.triangles.size());
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int on_edges = 0;
    for (size_t p = 0; p < mesh.triangles.size(); ++p) {
        const glm::dvec3 a(mesh.positions[mesh.triangles[p].x]);
        const glm::dvec3 b(mesh.positions[mesh.triangles[p].y]);
        const glm::dvec3 c(mesh.positions[mesh.triangles[p].z]);
        for (int k = 0; k < 500; ++k) {
            double s = u(rng), t = u(rng);
            if (s + t > 1.0) {
                s = 1.0 - s;
                t = 1.0 - t;
            }
            const glm::dvec3 x = a + s * (b - a) + t * (c - a);
            std::vector<uint32_t> holders;
            for (uint32_t i = first[p]; i < first[p + 1]; ++i) {
                if (contains(split.triangles[i], x, 1e-5)) {
                    holders.push_back(i);
                }
            }
            ASSERT_FALSE(holders.empty());
            on_edges += holders.size() > 1 ? 1 : 0;
            const uint32_t found = split_triangle_of(split, static_cast<uint32_t>(p), glm::vec3(x));
            EXPECT_NE(std::find(holders.begin(), holders.end(), found), holders.end())
                << "primitive " << p << " point " << k;
        }
    }
    EXPECT_LT(on_edges, 100);
}

// A camera looking down at a floor (y = 0) under a ceiling (y = 1), both 4 x 4.
Scene floor_and_ceiling() {
    return test::floor_and_ceiling(2.0f, "decomp_radiosity_source_planes");
}

// The distance along the ray (o, d) to triangle t's front, by the Moeller-Trumbore test in double.
std::optional<double> front_hit(const shared::NearTriangle& t, glm::dvec3 o, glm::dvec3 d) {
    const glm::dvec3 a(vec3_of(t.v0));
    const glm::dvec3 e1 = glm::dvec3(vec3_of(t.v1)) - a;
    const glm::dvec3 e2 = glm::dvec3(vec3_of(t.v2)) - a;
    if (glm::dot(glm::cross(e1, e2), d) >= 0.0) {
        return std::nullopt;
    }
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    const glm::dvec3 s = o - a;
    const double b1 = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double b2 = glm::dot(d, q) / det;
    const double distance = glm::dot(e2, q) / det;
    if (b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0 || distance <= 0.0) {
        return std::nullopt;
    }
    return distance;
}

// The options every render here shares: a size x size image at 2 camera samples per pixel, seed
// 5, the radiosity source over `path` with `iterations` iterations.
DecompositionOptions radiosity_source_options(const PathContinuation& path, int size, float alpha,
                                              float min_cluster_size, int cluster_rays,
                                              int iterations) {
    auto options = test::image_options<DecompositionOptions>(size, size, 2, 5);
    options.alpha = alpha;
    options.min_cluster_size = min_cluster_size;
    options.cluster_rays = cluster_rays;
    options.source = &path;
    options.radiosity_source = true;
    options.source_iterations = iterations;
    return options;
}

// The cluster rays of --decomp-source radiosity (decomp_cluster_hits): each kept ray's
// split_triangle is the split triangle whose front a brute-force ray test over all of them hits
// first (or one holding that hit point, on a shared edge), and -1 for the rays that miss.
TEST(DecompositionRadiositySource, ClusterRaysFindTheSplitTriangleTheyHit) {
    test::DeviceFrame device(floor_and_ceiling());
    PathContinuation path;
    IrradianceDecomposition decomposition(device.frame());
    const DecompositionOptions options = radiosity_source_options(path, 16, 0.3f, 1e5f, 512, 1);
    decomposition.render(options);
    const std::vector<shared::NearTriangle>& triangles = decomposition.near_triangles();
    ASSERT_GT(triangles.size(), 100u);
    std::vector<uint32_t> members;
    for (uint32_t i = 0; i < decomposition.camera_samples().size(); i += 2) {
        members.push_back(i);
    }
    const glm::dvec3 centre(decomposition.far_samples().at(0).centre);
    int hits = 0, misses = 0;
    for (const shared::ClusterRay& r : decomposition.cluster_rays(members, 3)) {
        const glm::dvec3 o = centre + glm::dvec3(vec3_of(r.offset));
        const glm::dvec3 d(vec3_of(r.direction));
        double nearest = INFINITY;
        int first = -1;
        for (size_t t = 0; t < triangles.size(); ++t) {
            const std::optional<double> h = front_hit(triangles[t], o, d);
            if (h && *h < nearest) {
                nearest = *h;
                first = static_cast<int>(t);
            }
        }
        if (r.kept == 0) {
            continue;
        }
        if (first < 0) {
            EXPECT_EQ(r.split_triangle, -1);
            ++misses;
            continue;
        }
        ++hits;
        ASSERT_GE(r.split_triangle, 0);
        if (r.split_triangle != first) {
            EXPECT_TRUE(contains(triangles[r.split_triangle], o + nearest * d, 1e-4))
                << "ray hits " << first << ", found " << r.split_triangle;
        }
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(misses, 5);
}

// A closed box of one diffuse material (reflectance rho) whose every surface emits Le, with a
// smaller emitting box inside (the furnace of tests/decomposition/decomposition_test.cpp): leaving
// emission out, every surface sends L* = rho Le / (1 - rho), whatever the geometry, and after k
// bounces of light L_k = rho Le (1 + rho + ... + rho^k) = L* (1 - rho^(k+1)). With --decomp-source
// radiosity, B^0 / pi is the direct part rho Le where the far field covers a triangle and the
// path-traced L* where it does not, and iteration k gathers B^k / pi = rho Le + rho x (the
// far field's and near field's B^(k-1) / pi): the covered triangles' B^k lies between L_k (had
// every ray hit a covered triangle) and L*.
using test::kFurnaceEmission;
using test::kFurnaceReflectance;

Scene furnace_box() { return test::furnace_box("decomp_radiosity_source_furnace"); }

double furnace_bounces(int k) {
    const double rho = kFurnaceReflectance;
    return rho * kFurnaceEmission / (1.0 - rho) * (1.0 - std::pow(rho, k + 1));
}

// A render of the furnace by --decomp-source radiosity after `iterations` iterations, with or
// without the extrapolated tail: the covered split triangles' B(t) / pi (area-weighted mean, and
// the worst channel's relative distance from `expected`), the image's mean indirect light.
struct FurnaceRender {
    double mean = 0.0, worst = 0.0, reflected = 0.0, tail_ratio = 0.0;
};

FurnaceRender render_furnace(test::DeviceFrame& device, int iterations, bool extrapolate,
                             double expected) {
    PathContinuation path;
    IrradianceDecomposition decomposition(device.frame());
    // One cluster (a minimum size beyond the box): one far-field sample.
    DecompositionOptions options =
        radiosity_source_options(path, 16, 0.4f, 1e5f, 16384, iterations);
    options.radiosity_samples = 256;
    options.traced_samples = 256;
    options.source_extrapolate = extrapolate;
    DecompositionStats stats;
    const Image image = decomposition.render(options, &stats);
    EXPECT_EQ(decomposition.far_samples().size(), 1u);
    EXPECT_EQ(stats.source_change.size(), static_cast<size_t>(iterations));
    EXPECT_EQ(stats.source_rays_without_triangle, 0u);
    const std::vector<glm::vec3> radiance = decomposition.near_radiance();
    const std::vector<shared::NearTriangle>& triangles = decomposition.near_triangles();
    std::vector<bool> traced(triangles.size(), false);
    for (uint32_t t : decomposition.uncovered_triangles()) {
        traced[t] = true;
    }
    FurnaceRender out;
    out.tail_ratio = stats.source_tail_ratio;
    double sum = 0.0, area = 0.0;
    for (size_t t = 0; t < triangles.size(); ++t) {
        if (traced[t]) {
            continue;
        }
        const glm::vec3 e1 = vec3_of(triangles[t].v1) - vec3_of(triangles[t].v0);
        const glm::vec3 e2 = vec3_of(triangles[t].v2) - vec3_of(triangles[t].v0);
        const double a = 0.5 * glm::length(glm::cross(e1, e2));
        for (int c = 0; c < 3; ++c) {
            sum += a * radiance[t][c];
            out.worst = std::max(out.worst, std::abs(radiance[t][c] - expected) / expected);
        }
        area += 3.0 * a;
    }
    const Image indirect = select_layers(image, {"indirect"});
    double pixels = 0.0;
    for (float v : indirect.pixels) {
        pixels += v;
    }
    out.mean = sum / area;
    out.reflected = pixels / indirect.pixels.size();
    std::printf(
        "furnace, %d iterations%s: B(t) / pi mean %.4f (expected %.4f), worst triangle %.3f off; "
        "indirect mean %.4f (rho times expected %.4f)\n",
        iterations, extrapolate ? " and the tail" : "", out.mean, expected, out.worst,
        out.reflected, kFurnaceReflectance * expected);
    return out;
}

// Without the tail (--decomp-extrapolate off), after 12 iterations the covered triangles' mean
// B(t) / pi and the image's mean indirect light are L_12 = 2.996 (L* = 3) within 2 % and 3 %,
// each triangle within 6 % (measured: 0.1 %, 0.1 %, 3.2 %); after 1 iteration B(t) / pi lies
// between L_1 = 1.92 and 0.95 L* (measured 2.61: some rays read path-traced triangles) and the
// indirect light above rho L_1 (measured 1.71; the image reads B^1 of every triangle,
// path-traced ones included), so an iteration that stopped short of the far field's refit or ran
// to convergence whatever K would fail.
TEST(DecompositionRadiositySource, IteratedRadiosityInAFurnaceFollowsItsBounces) {
    test::DeviceFrame device(furnace_box());
    const double converged = furnace_bounces(1000);
    const double l1 = furnace_bounces(1);
    const FurnaceRender one = render_furnace(device, 1, false, l1);
    EXPECT_GT(one.mean, 0.98 * l1);
    EXPECT_LT(one.mean, 0.95 * converged);
    EXPECT_GT(one.reflected, 0.98 * kFurnaceReflectance * l1);
    const double l12 = furnace_bounces(12);
    const FurnaceRender twelve = render_furnace(device, 12, false, l12);
    EXPECT_NEAR(twelve.mean, l12, 0.02 * l12);
    EXPECT_NEAR(twelve.reflected, kFurnaceReflectance * l12, 0.03 * kFurnaceReflectance * l12);
    EXPECT_LT(twelve.worst, 0.06);
    EXPECT_EQ(twelve.tail_ratio, 0.0);
}

// With the tail (the default), 2 and 3 iterations come close to the converged L* = rho Le /
// (1 - rho) that the bounce series sums to: the covered triangles' mean B(t) / pi is less than
// 0.4 times as far from L* as where the iterations stop without it, and not above L* by more than
// 1 % (measured: 2.9756 against 2.9034 after 2 iterations, 2.9922 against 2.9717 after 3; 0.25
// and 0.28 times as far; 12 plain iterations give 2.9937). The ratio of the last two changes is
// the tail's, between 0 and 0.9 (measured 0.20 and 0.23: the path-traced triangles hold L*
// from the start, so the change shrinks faster than rho = 0.6 per bounce).
TEST(DecompositionRadiositySource, ExtrapolatedTailInAFurnaceReachesTheConvergedRadiosity) {
    test::DeviceFrame device(furnace_box());
    const double converged = furnace_bounces(1000);
    for (int k : {2, 3}) {
        const FurnaceRender tail = render_furnace(device, k, true, converged);
        const FurnaceRender plain = render_furnace(device, k, false, converged);
        EXPECT_LT(std::abs(tail.mean - converged), 0.4 * std::abs(plain.mean - converged))
            << k << " iterations";
        EXPECT_LT(tail.mean, 1.01 * converged) << k << " iterations";
        EXPECT_GT(tail.tail_ratio, 0.0) << k << " iterations";
        EXPECT_LE(tail.tail_ratio, 0.9) << k << " iterations";
        EXPECT_EQ(plain.tail_ratio, 0.0) << k << " iterations";
    }
}

Image render_cornell(size_t local_size, size_t max_chunk, int iterations = 3) {
    Context context(test::chunked_context_options(local_size, max_chunk));
    test::DeviceFrame device(test::load_cornell_box(), context);
    PathContinuation path;
    IrradianceDecomposition decomposition(device.frame());
    return decomposition.render(radiosity_source_options(path, 24, 30.0f, 30.0f, 256, iterations));
}

// Same seed and options: the same image, bit for bit, whatever the chunking and the work-group
// size (the rays' split triangles, the refits and the gathers run per item, the sums in ray and
// list order); the iterations change it.
TEST(DecompositionRadiositySource, ImageIsBitwiseIdenticalAcrossChunksAndWorkGroups) {
    const Image reference = render_cornell(0, 0);
    EXPECT_TRUE(test::bitwise_equal(reference, render_cornell(8, 1000))) << "local 8, chunk 1000";
    EXPECT_TRUE(test::bitwise_equal(reference, render_cornell(32, 333))) << "local 32, chunk 333";
    EXPECT_FALSE(test::bitwise_equal(reference, render_cornell(0, 0, 1)));
}

}  // namespace
}  // namespace rc
