// Shared pieces of the tests: one OpenCL context per test program, paths, running the CLI.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/device_bvh.h"
#include "device/context.h"
#include "image/image.h"
#include "methods/frame_scene.h"
#include "methods/method.h"
#include "scene/device_scene.h"
#include "scene/scene.h"

namespace rc::test {

// The context every device test of this program shares (the device of test_device.h, kernel
// binary cache in the build tree).
Context& shared_context();

// A fresh context with the given options on the same device.
ContextOptions default_context_options();

// default_context_options() with work groups of `local_size` items and launches of at most
// `max_chunk_items` (0: the defaults): what the tests of results independent of chunking vary.
ContextOptions chunked_context_options(size_t local_size, size_t max_chunk_items);

// A context whose programs traverse the BVH in `layout`, one per layout per test program.
Context& layout_context(BvhLayout layout);

std::filesystem::path source_dir();
std::filesystem::path radcache_executable();
// The kernel binary cache (and --method auto's throughput file) the suite's renders share.
std::filesystem::path kernel_cache_dir();
Scene load_cornell_box();
// The scene of `path` posed at `frame`.
Scene load_scene_at_frame(const std::filesystem::path& path, int frame);
// A camera at (0, 0.9, 0) looking down at a diffuse floor (y = 0) under a ceiling (y = 1), both
// 2 half_size across, with a small area light under the ceiling's centre; written under
// scratch_dir(scratch).
Scene floor_and_ceiling(float half_size, const std::string& scratch);
// A furnace: a closed box (inward faces) with a block standing on its floor, every surface diffuse
// with reflectance kFurnaceReflectance and emitting radiance kFurnaceEmission; written under
// scratch_dir(scratch).
constexpr float kFurnaceReflectance = 0.6f;
constexpr float kFurnaceEmission = 2.0f;
Scene furnace_box(const std::string& scratch);

// A Phong material with white specular reflectance and no diffuse lobe ("phong E").
Material pure_phong(float exponent);

// The shipped reference of scenes/<scene>/ (512 x 512): its layer `layer`, box filtered to
// size x size.
Image scene_reference(const std::string& scene, const std::string& layer, int size);
// scene_reference("cornell-box", layer, size).
Image cornell_reference(const std::string& layer, int size);

// A scene with its BVH and both on a device: the FrameScene a method's classes take.
struct DeviceFrame {
    explicit DeviceFrame(Scene loaded, Context& device = shared_context());
    FrameScene frame() { return {context, scene, device_bvh, device_scene}; }

    Context& context;
    Scene scene;
    Bvh bvh;
    DeviceBvh device_bvh;
    DeviceScene device_scene;
};

// A new empty directory under the build tree's test scratch area, in a folder of the running
// test's own (tests run in parallel processes), removed by nobody.
std::filesystem::path scratch_dir(const std::string& name);

// Whether `method` declares the command-line option `option` ("--ic-rays").
bool declares(const MethodEntry& method, const std::string& option);

// Options that make a render with `method` small and quick: its costliest knobs turned down
// (record rays, photons, gather rays, split triangles, ...) where it declares them and `options`,
// the render's other options, leave them unset; the grid's photons only where `options` make a
// grid.
std::vector<std::string> quick_method_options(const MethodEntry& method,
                                              const std::vector<std::string>& options = {});

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};
// Runs `radcache <args>` with optional environment assignments ("NAME=value"), on the tests'
// device (RADCACHE_DEVICE, test_device.h) unless they name another; with a test device named,
// $RADCACHE_ALLOW_LOOP_CAP=1 (host/device/device_features.h).
CommandResult run_radcache(const std::vector<std::string>& args,
                           const std::vector<std::string>& environment = {});

}  // namespace rc::test
