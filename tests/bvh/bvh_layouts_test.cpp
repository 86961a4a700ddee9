// The BVH layouts answer rays the same (docs/bvh.md): the same closest hit, bit for bit (the
// closest-hit choice does not depend on the order triangles are tested in), and the same any-hit
// answer, but for rare hits at the triangle test's noise floor near the ray's origin, which one
// layout's boxes cull and the other's do not; every method renders the same image, bit for bit,
// in either layout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "bvh/device_tracer.h"
#include "image/image_io.h"
#include "methods/registry.h"
#include "ray_sets.h"
#include "reference_intersector.h"
#include "scene/generated_meshes.h"
#include "test_support.h"

namespace rc {
namespace {

struct LayoutAnswers {
    std::vector<shared::Hit> closest;
    std::vector<unsigned> occluded;
};

LayoutAnswers trace(const TriangleMesh& mesh, BvhLayout layout,
                    const std::vector<shared::Ray>& rays) {
    Context& context = test::layout_context(layout);
    const Bvh bvh = build_bvh(mesh, layout);
    const DeviceBvh device_bvh(context, bvh);
    DeviceTracer tracer(context, device_bvh);
    return {tracer.trace_closest(rays), tracer.trace_any(rays)};
}

// Whether the answers of the layouts, where they differ, are both ones rounding allows, and the
// nearer closest hit is one rounding makes possible but not certain: a hit at the noise floor of
// the triangle test, which one layout tests and the other culls with a box (docs/bvh.md).
bool is_rounding_difference(const TriangleMesh& mesh, const shared::Ray& ray, const shared::Hit& a,
                            const shared::Hit& b) {
    if (!test::closest_hit_is_valid(mesh, ray, a.primitive) ||
        !test::closest_hit_is_valid(mesh, ray, b.primitive)) {
        return false;
    }
    const shared::Hit& nearer = a.t < b.t ? a : b;
    return !test::reference_intersect(mesh, nearer.primitive, ray).certain;
}

// Random rays, bounces off the surfaces, and rays aimed exactly at vertices and edges (where
// triangles tie): the same answers, bit for bit, but for rounding differences, which must be
// rare.
void expect_same_answers(const TriangleMesh& mesh, uint32_t seed, const char* label) {
    const test::Bounds bounds = test::mesh_bounds(mesh);
    std::vector<shared::Ray> rays = test::random_rays(bounds, 20000, seed);
    for (const test::AimedRays& aimed : {test::vertex_aimed_rays(mesh, bounds, 20000, seed + 1),
                                         test::edge_aimed_rays(mesh, bounds, 20000, seed + 2)}) {
        rays.insert(rays.end(), aimed.rays.begin(), aimed.rays.end());
    }
    {
        Context& context = test::layout_context(BvhLayout::kBvh4);
        const Bvh bvh = build_bvh(mesh, BvhLayout::kBvh4);
        const DeviceBvh device_bvh(context, bvh);
        DeviceTracer tracer(context, device_bvh);
        const std::vector<shared::Ray> bounces = tracer.diffuse_bounce_rays(rays, seed + 3);
        rays.insert(rays.end(), bounces.begin(), bounces.end());
    }
    const LayoutAnswers bvh4 = trace(mesh, BvhLayout::kBvh4, rays);
    const LayoutAnswers wide = trace(mesh, BvhLayout::kWide, rays);
    size_t hits = 0;
    size_t closest_rounding = 0;
    size_t any_rounding = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        hits += bvh4.closest[i].primitive != RC_NO_HIT;
        if (std::memcmp(&bvh4.closest[i], &wide.closest[i], sizeof(shared::Hit)) != 0) {
            ++closest_rounding;
            EXPECT_TRUE(is_rounding_difference(mesh, rays[i], bvh4.closest[i], wide.closest[i]))
                << label << " ray " << i << ": bvh4 hit " << bvh4.closest[i].primitive << " at t "
                << bvh4.closest[i].t << ", wide hit " << wide.closest[i].primitive << " at t "
                << wide.closest[i].t;
        }
        if (bvh4.occluded[i] != wide.occluded[i]) {
            ++any_rounding;
            EXPECT_TRUE(test::any_hit_is_valid(mesh, rays[i], bvh4.occluded[i] != 0) &&
                        test::any_hit_is_valid(mesh, rays[i], wide.occluded[i] != 0))
                << label << " ray " << i;
        }
    }
    std::printf("%-14s %zu rays, %zu hits: closest hits differ on %zu, any hit on %zu\n", label,
                rays.size(), hits, closest_rounding, any_rounding);
    EXPECT_LE(closest_rounding, rays.size() / 2000) << label;
    EXPECT_LE(any_rounding, rays.size() / 2000) << label;
    EXPECT_GT(hits, rays.size() / 4) << label << ": the rays hit the mesh";
}

TEST(BvhLayouts, SameHitsOnTheCornellBox) {
    expect_same_answers(test::load_cornell_box().mesh, 41, "Cornell box");
}

TEST(BvhLayouts, SameHitsOnATriangleSoup) {
    // Overlapping, intersecting triangles: many rays cross several at nearly the same t.
    expect_same_answers(make_triangle_soup(20000, 9, glm::vec3(-1.0f), glm::vec3(1.0f), 0.3f), 51,
                        "triangle soup");
}

TEST(BvhLayouts, SameHitsOnADenseSphere) {
    expect_same_answers(make_icosphere(glm::vec3(0.5f, -2.0f, 3.0f), 2.0f, 6, 0.05f, 7.0f), 61,
                        "dense sphere");
}

bool declares(const MethodEntry& method, const std::string& option) {
    return std::any_of(method.options.begin(), method.options.end(),
                       [&](const OptionSpec& spec) { return spec.name == option; });
}

// One method's quick render of a shipped scene in `layout`: its costliest knobs turned down
// where it declares them.
Image render(const MethodEntry& method, const std::string& scene, BvhLayout layout) {
    const std::string name = bvh_layout_name(layout);
    const auto output =
        test::scratch_dir("bvh_layouts_" + method.name + "_" + scene + "_" + name) / "image.exr";
    std::vector<std::string> args = {
        "render",   (test::source_dir() / "scenes" / scene / "scene.json").string(),
        "-o",       output.string(),
        "--method", method.name,
        "--bvh",    name,
        "--width",  "48",
        "--height", "40",
        "--spp",    "2",
        "--seed",   "3",
        "-q"};
    if (declares(method, "--photons") && !declares(method, "--ic-ivg")) {
        args.insert(args.end(), {"--photons", "20000"});
    }
    if (declares(method, "--ic-rays")) {
        args.insert(args.end(), {"--ic-rays", "32"});
    }
    const test::CommandResult result = test::run_radcache(args);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_image(output);
}

class EveryMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethod, RendersTheSameImageInBothLayouts) {
    const MethodEntry& method = find_method(GetParam());
    for (const char* scene : {"cornell-box", "glossy-box"}) {
        SCOPED_TRACE(scene);
        const Image bvh4 = render(method, scene, BvhLayout::kBvh4);
        const Image wide = render(method, scene, BvhLayout::kWide);
        ASSERT_EQ(bvh4.channel_names, wide.channel_names);
        ASSERT_EQ(bvh4.pixels.size(), wide.pixels.size());
        ASSERT_FALSE(bvh4.pixels.empty());
        size_t differ = 0;
        for (size_t i = 0; i < bvh4.pixels.size(); ++i) {
            differ += std::memcmp(&bvh4.pixels[i], &wide.pixels[i], sizeof(float)) != 0;
        }
        EXPECT_EQ(differ, 0u) << "of " << bvh4.pixels.size() << " channel values";
    }
}

std::vector<std::string> method_names_list() {
    std::vector<std::string> names;
    for (const MethodEntry& method : method_registry()) {
        names.push_back(method.name);
    }
    return names;
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryMethod, ::testing::ValuesIn(method_names_list()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace rc
