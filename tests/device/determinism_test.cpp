// Determinism: a kernel-rendered image is bitwise identical across runs, chunk sizes and
// work-group sizes (DESIGN.md §1.2).
#include <gtest/gtest.h>

#include <cstring>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "methods/normals/normals.h"
#include "scene/device_scene.h"
#include "test_support.h"

namespace rc {
namespace {

Image render_with(size_t local_size, size_t max_chunk, const Scene& scene) {
    Context context(test::chunked_context_options(local_size, max_chunk));
    test::DeviceFrame device(scene, context);
    NormalsMethod method(device.frame());
    NormalsOptions render;
    render.width = 160;
    render.height = 120;
    render.samples_per_pixel = 4;  // jittered: exercises the RNG
    render.seed = 1234;
    return method.render(render);
}

bool bitwise_equal(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(Determinism, NormalsImageIsBitwiseIdenticalAcrossRunsChunksAndWorkGroups) {
    const Scene scene = test::load_cornell_box();
    const Image reference = render_with(0, 0, scene);
    EXPECT_TRUE(bitwise_equal(reference, render_with(0, 0, scene))) << "second run";
    EXPECT_TRUE(bitwise_equal(reference, render_with(8, 1000, scene))) << "local 8, chunk 1000";
    EXPECT_TRUE(bitwise_equal(reference, render_with(32, 4096, scene))) << "local 32, chunk 4096";
    // The image is not trivially constant.
    float lowest = reference.pixels[0];
    float highest = reference.pixels[0];
    for (float v : reference.pixels) {
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
    }
    EXPECT_LT(lowest, highest);
}

TEST(Determinism, DifferentSeedsGiveDifferentJitter) {
    test::DeviceFrame cornell(test::load_cornell_box());
    NormalsMethod method(cornell.frame());
    NormalsOptions options;
    options.width = 64;
    options.height = 64;
    options.samples_per_pixel = 4;
    options.seed = 1;
    const Image a = method.render(options);
    options.seed = 2;
    const Image b = method.render(options);
    EXPECT_FALSE(bitwise_equal(a, b));
}

}  // namespace
}  // namespace rc
