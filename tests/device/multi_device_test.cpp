// Rendering on several devices (`--device all`, `--device P:D,P:D`): with PoCL
// exposing two CPU devices (POCL_DEVICES="pthread pthread"), the path tracer's image is bitwise
// the single-device image whatever the devices' order, chunking and work-group size, both devices
// render a share that adds up to the image (stats); so are the grid methods' images, their
// photons shared, irradiance caching's, radiance caching's and SDRC's (diffuse record batches and
// final pass shared), irradiance decomposition's (its pass 2 shared) and the normals preview's;
// temporal caching (which renders on one device), a device named twice, an empty entry, --time
// and intermediate images are refused with exit status 2 and no output; a device that fails
// mid-render (pt, ic) stops the render with one line naming that device and the call, and no
// output file. Skipped where PoCL does not give two devices, or the tests run on another device.
// Over two platforms (PoCL and Mesa's rusticl, where installed): the path tracer's image within
// noise of PoCL's alone, both devices given pixels, and a failing device named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/render_devices.h"
#include "device/device_list.h"
#include "device/fault_injection.h"
#include "image/image.h"
#include "image/image_io.h"
#include "test_device.h"
#include "test_support.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {
namespace {

const std::string kTwoDevices = "POCL_DEVICES=pthread pthread";

// Whether the tests run on PoCL (RADCACHE_TEST_DEVICE unset, or naming PoCL's device): the
// MultiDevice tests split over PoCL's two devices whatever the tests' device, so they run in the
// suite's PoCL pass; on another implementation they would compare PoCL's images with that one's.
bool tests_run_on_pocl() {
    const std::string spec = test::test_device_spec();
    return spec.empty() || is_pocl(select_device(list_devices(), spec));
}

bool two_devices() {
    const test::CommandResult result = test::run_radcache({"devices"}, {kTwoDevices});
    return result.exit_code == 0 && result.output.find("0:1") != std::string::npos;
}

constexpr const char* kNotOnPocl =
    "the tests' device is not PoCL's: these split over PoCL's two devices (POCL_DEVICES) and run "
    "in the suite's PoCL pass";

std::string cornell() {
    return (test::source_dir() / "scenes" / "cornell-box" / "scene.json").string();
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// `radcache render` of `scene` (the Cornell box) at 40 x 36, 8 spp with `options` into
// dir/name.exr (every layer) and its stats; exit status 0 expected.
nlohmann::json render(const std::filesystem::path& dir, const std::string& name,
                      const std::vector<std::string>& options,
                      const std::string& scene = cornell()) {
    std::vector<std::string> args = {"render",   scene,
                                     "--width",  "40",
                                     "--height", "36",
                                     "--spp",    "8",
                                     "-o",       (dir / (name + ".exr")).string(),
                                     "--stats",  (dir / (name + ".json")).string(),
                                     "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CommandResult result = test::run_radcache(args, {kTwoDevices});
    EXPECT_EQ(result.exit_code, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(read_file(dir / (name + ".json")));
    return stats.contains("frames") ? stats["frames"][0] : stats;
}

struct SplitRender {
    nlohmann::json one;  // the frame's stats on device 0:0
    nlohmann::json two;  // and with `devices`
};

// `options` rendered on device 0:0 (dir/NAME_one) and with `devices` (dir/NAME_two): every layer
// of the two images expected bitwise equal.
SplitRender render_one_and_split(const std::filesystem::path& dir, const std::string& name,
                                 const std::vector<std::string>& options,
                                 const std::vector<std::string>& devices,
                                 const std::string& scene = cornell()) {
    std::vector<std::string> one = options;
    one.insert(one.end(), {"--device", "0:0"});
    std::vector<std::string> two = options;
    two.insert(two.end(), devices.begin(), devices.end());
    SplitRender result{render(dir, name + "_one", one, scene),
                       render(dir, name + "_two", two, scene)};
    EXPECT_TRUE(
        same_pixels(read_image(dir / (name + "_two.exr")), read_image(dir / (name + "_one.exr"))))
        << name;
    return result;
}

TEST(MultiDevice, PathTracerImageIsTheOneDeviceImageWhateverTheSplit) {
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_pt");
    render(dir, "one", {"--device", "0:0"});
    const Image expected = read_image(dir / "one.exr");
    for (const auto& [name, options] :
         std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"pair", {"--device", "0:0,0:1"}},
             {"all", {"--device", "all"}},
             {"swapped", {"--device", "0:1, 0:0", "--max-chunk", "100", "--local-size", "8"}}}) {
        const nlohmann::json stats = render(dir, name, options);
        EXPECT_TRUE(same_pixels(read_image(dir / (name + ".exr")), expected)) << name;
        const nlohmann::json& devices = stats.at("devices");
        ASSERT_EQ(devices.size(), 2u) << name;
        size_t pixels = 0;
        for (const nlohmann::json& d : devices) {
            EXPECT_GT(d.at("chunks").get<size_t>(), 0u) << name;
            EXPECT_GT(d.at("rays").get<uint64_t>(), 0u) << name;
            pixels += d.at("pixels").get<size_t>();
        }
        EXPECT_EQ(pixels, 40u * 36u) << name;
    }
}

// The irradiance vector grid's photons shared by the two devices: the grid's fixed-point sums are
// added exactly, so `ivg` and `ivg-gather` images are bitwise the one-device images, and both
// devices traced photons that add up to the grid's.
TEST(MultiDevice, GridMethodsImageIsTheOneDeviceImage) {
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_ivg");
    for (const std::string method : {"ivg", "ivg-gather"}) {
        const nlohmann::json stats =
            render_one_and_split(dir, method, {"--method", method}, {"--device", "0:1,0:0"}).two;
        const nlohmann::json& grid = stats.at("grid");
        ASSERT_EQ(grid.at("devices").size(), 2u) << method;
        uint64_t photons = 0;
        for (const nlohmann::json& d : grid.at("devices")) {
            EXPECT_GT(d.at("batches").get<size_t>(), 0u) << method;
            photons += d.at("photons").get<uint64_t>();
        }
        EXPECT_EQ(photons, grid.at("photons").get<uint64_t>()) << method;
    }
}

// Irradiance caching on two devices: the record batches' hemisphere sampling in record ranges
// and the final pass in chunks of rows, so every layer is bitwise the one-device image whatever
// the devices' order, chunking and work-group size, with one or two cache levels and with the
// grid read beyond the hemisphere hits (--ic-ivg: its records on the first device); both devices
// computed records (adding up to the cache's) and rendered chunks (adding up to the image).
TEST(MultiDevice, IrradianceCacheImageIsTheOneDeviceImageWhateverTheSplit) {
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_ic");
    struct Case {
        std::string name;
        std::vector<std::string> method;  // the same on one and two devices
        std::vector<std::string> devices;
        bool records_split;
    };
    const std::vector<std::string> ic = {"--method", "ic", "--ic-rays", "256"};
    auto with = [&](std::vector<std::string> more) {
        more.insert(more.begin(), ic.begin(), ic.end());
        return more;
    };
    for (const Case& c : std::vector<Case>{
             {"two_levels", ic, {"--device", "0:0,0:1"}, true},
             {"swapped",
              ic,
              {"--device", "0:1, 0:0", "--max-chunk", "100", "--local-size", "8"},
              true},
             {"one_level", with({"--ic-bounces", "1"}), {"--device", "all"}, true},
             {"grid", with({"--ic-bounces", "1", "--ic-ivg"}), {"--device", "all"}, false}}) {
        const auto [single, stats] = render_one_and_split(dir, c.name, c.method, c.devices);
        EXPECT_EQ(stats.at("level_records"), single.at("level_records")) << c.name;
        EXPECT_EQ(stats.at("record_rays"), single.at("record_rays")) << c.name;
        const nlohmann::json& devices = stats.at("devices");
        ASSERT_EQ(devices.size(), 2u) << c.name;
        size_t records = 0;
        size_t pixels = 0;
        for (const nlohmann::json& d : devices) {
            EXPECT_GT(d.at("chunks").get<size_t>(), 0u) << c.name;
            EXPECT_EQ(d.at("records").get<size_t>() > 0, c.records_split) << c.name;
            records += d.at("records").get<size_t>();
            pixels += d.at("pixels").get<size_t>();
        }
        size_t computed = 0;
        for (const nlohmann::json& level : stats.at("level_records")) {
            computed += level.get<size_t>();
        }
        EXPECT_EQ(records, c.records_split ? computed : 0u) << c.name;
        EXPECT_EQ(pixels, 40u * 36u) << c.name;
    }
}

// Radiance caching and SDRC on glossy-box: their diffuse records' batches and the final pass
// shared (the glossy buffer copied from the first device), their own records on the first
// device, so every layer (the glossy caches' own included) is bitwise the one-device image; both
// devices computed diffuse records and rendered chunks.
TEST(MultiDevice, GlossyCachesImageIsTheOneDeviceImage) {
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_glossy");
    const std::string glossy_box =
        (test::source_dir() / "scenes" / "glossy-box" / "scene.json").string();
    for (const std::string method : {"rc", "sdrc"}) {
        const std::vector<std::string> options = {"--method", method, "--ic-rays", "256"};
        const nlohmann::json stats =
            render_one_and_split(dir, method, options, {"--device", "0:1,0:0"}, glossy_box).two;
        const nlohmann::json& devices = stats.at("devices");
        ASSERT_EQ(devices.size(), 2u) << method;
        for (const nlohmann::json& d : devices) {
            EXPECT_GT(d.at("records").get<size_t>(), 0u) << method;
            EXPECT_GT(d.at("chunks").get<size_t>(), 0u) << method;
        }
    }
}

// The geometry preview's rows shared by the two devices: bitwise the one-device image.
TEST(MultiDevice, NormalsImageIsTheOneDeviceImage) {
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_normals");
    const nlohmann::json stats = render_one_and_split(dir, "normals", {"--method", "normals"},
                                                      {"--device", "0:1,0:0", "--max-chunk", "64"})
                                     .two;
    const nlohmann::json& devices = stats.at("devices");
    ASSERT_EQ(devices.size(), 2u);
    size_t pixels = 0;
    for (const nlohmann::json& d : devices) {
        EXPECT_GT(d.at("chunks").get<size_t>(), 0u);
        pixels += d.at("pixels").get<size_t>();
    }
    EXPECT_EQ(pixels, 40u * 36u);
}

// Irradiance decomposition on two devices: the grid's photons, pass 2 (both terms at the camera
// samples and the render pass, in chunks of rows) and, with path-traced continuation, the split
// triangles' coarse radiosity and the clusters' batches shared, so every layer (far and near field
// included) is bitwise the one-device image whatever the devices' order, chunking and work-group
// size, with the grid and with path-traced continuation as the coarse solution; the far field is
// the same, both devices rendered chunks that add up to the image and (path) computed radiosities
// and fitted clusters that add up to the frame's.
TEST(MultiDevice, DecompositionImageIsTheOneDeviceImageWhateverTheSplit) {
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_decomposition");
    struct Case {
        std::string name;
        std::vector<std::string> method;  // the same on one and two devices
        std::vector<std::string> devices;
        // Path-traced continuation: the coarse radiosity and the cluster batches shared.
        bool path_split;
    };
    // With camera samples past the fully shaded ones (--decomp-indirect-spp): their terms and
    // their indirect light in each device's chunks too.
    const std::vector<std::string> grid = {"--method", "decomposition", "--decomp-indirect-spp",
                                           "12"};
    // Fewer split triangles: their path-traced radiosity is most of the render.
    const std::vector<std::string> path = {"--method", "decomposition", "--decomp-source",
                                           "path",     "--alpha",       "3%"};
    for (const Case& c :
         std::vector<Case>{{"grid", grid, {"--device", "0:0,0:1"}, false},
                           {"path", path, {"--device", "all"}, true},
                           {"swapped",
                            path,
                            {"--device", "0:1, 0:0", "--max-chunk", "100", "--local-size", "8"},
                            true}}) {
        const auto [single, stats] = render_one_and_split(dir, c.name, c.method, c.devices);
        EXPECT_EQ(stats.at("sh_samples"), single.at("sh_samples")) << c.name;
        EXPECT_EQ(stats.at("shading_rays"), single.at("shading_rays")) << c.name;
        EXPECT_EQ(stats.at("cluster_rays_traced"), single.at("cluster_rays_traced")) << c.name;
        EXPECT_FALSE(single.contains("devices")) << c.name;
        const nlohmann::json& devices = stats.at("devices");
        ASSERT_EQ(devices.size(), 2u) << c.name;
        size_t pixels = 0;
        size_t clusters = 0;
        uint64_t cluster_rays = 0;
        size_t triangles = 0;
        uint64_t radiosity_rays = 0;
        for (const nlohmann::json& d : devices) {
            EXPECT_GT(d.at("chunks").get<size_t>(), 0u) << c.name;
            EXPECT_GT(d.at("shading_rays").get<uint64_t>(), 0u) << c.name;
            EXPECT_EQ(d.at("clusters").get<size_t>() > 0, c.path_split) << c.name;
            pixels += d.at("pixels").get<size_t>();
            clusters += d.at("clusters").get<size_t>();
            cluster_rays += d.at("cluster_rays").get<uint64_t>();
            EXPECT_EQ(d.at("radiosity_triangles").get<size_t>() > 0, c.path_split) << c.name;
            triangles += d.at("radiosity_triangles").get<size_t>();
            radiosity_rays += d.at("radiosity_rays").get<uint64_t>();
        }
        EXPECT_EQ(stats.at("radiosity_rays"), single.at("radiosity_rays")) << c.name;
        EXPECT_EQ(triangles, c.path_split ? stats["triangles"].at("near").get<size_t>() : 0u)
            << c.name;
        EXPECT_EQ(radiosity_rays, c.path_split ? stats.at("radiosity_rays").get<uint64_t>() : 0u)
            << c.name;
        EXPECT_EQ(pixels, 40u * 36u) << c.name;
        EXPECT_EQ(clusters, c.path_split ? stats.at("clusters_sampled").get<size_t>() : 0u)
            << c.name;
        EXPECT_EQ(cluster_rays, c.path_split ? stats.at("cluster_rays_traced").get<uint64_t>() : 0u)
            << c.name;
    }
}

TEST(MultiDevice, WhatRendersOnOneDeviceIsRefusedByName) {
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    const auto dir = test::scratch_dir("multi_device_refused");
    const std::string out = (dir / "x.exr").string();
    struct Case {
        std::vector<std::string> options;
        std::string names;
    };
    for (const Case& c : std::vector<Case>{
             {{"--method", "ic", "--temporal", "--device", "all"},
              "--temporal renders on one device"},
             {{"--method", "rc", "--temporal", "--device", "0:0,0:1"},
              "--temporal renders on one device"},
             {{"--method", "decomposition", "--decomp-source", "radiosity", "--device", "all"},
              "--decomp-source radiosity renders on one device"},
             {{"--device", "0:0,0:0"}, "twice"},
             {{"--device", "0:0,"}, "empty entry"},
             {{"--device", "0:0,7:7"}, "7:7"},
             {{"--device", "all", "--time", "1"}, "--time"},
             {{"--device", "all", "--save-every-pow2"}, "--save-every-pow2"}}) {
        std::vector<std::string> args = {"render",   cornell(), "--width", "8",
                                         "--height", "8",       "-o",      out};
        args.insert(args.end(), c.options.begin(), c.options.end());
        const test::CommandResult result = test::run_radcache(args, {kTwoDevices});
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find(c.names), std::string::npos) << result.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.names;
    }
}

// Commands other than render use one device: a list or `all` is refused by name (exit 2).
TEST(MultiDevice, OtherCommandsRefuseSeveralDevices) {
    for (const std::string spec : {"all", "0:0,0:1"}) {
        const test::CommandResult result =
            test::run_radcache({"warmup", "--method", "pt", "--device", spec}, {kTwoDevices});
        EXPECT_EQ(result.exit_code, 2) << result.output;
        EXPECT_NE(result.output.find("names several devices"), std::string::npos) << result.output;
    }
}

// The render of `options` on both devices in this process with the `nth` kernel launch failing
// (CL_OUT_OF_RESOURCES), on whichever device made it: exit status 1, one line naming that device
// and the call, nothing left in the output's directory.
void expect_failing_device_named(const std::string& name, const std::vector<std::string>& options,
                                 uint64_t nth, const std::string& devices = "0:0,0:1") {
    const auto dir = test::scratch_dir(name);
    const auto out = dir / "x.exr";
    std::vector<std::string> args = {cornell(), "--width", "40",         "--height",
                                     "36",      "--spp",   "8",          "--device",
                                     devices,   "-o",      out.string(), "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    arm_device_fault("clEnqueueNDRangeKernel", nth, -5);
    int exit_code = 0;
    std::string message;
    try {
        exit_code = run_render_command(args);
    } catch (const Error& error) {
        exit_code = error.exit_code();
        message = error.what();
    }
    const bool fired = device_fault_fired();
    disarm_device_fault();
    ASSERT_TRUE(fired) << name;
    EXPECT_EQ(exit_code, 1) << name;
    bool named = false;
    for (size_t start = 0; start <= devices.size();) {
        const size_t comma = std::min(devices.find(',', start), devices.size());
        named =
            named || message.rfind("device " + devices.substr(start, comma - start) + " (", 0) == 0;
        start = comma + 1;
    }
    EXPECT_TRUE(named) << message;
    EXPECT_NE(message.find("clEnqueueNDRangeKernel"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_FALSE(std::filesystem::exists(out)) << name;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        ADD_FAILURE() << "left behind: " << entry.path();
    }
}

// Kernel launches of a render of `options` on both devices, counted in this process.
uint64_t kernel_launches(const std::vector<std::string>& options) {
    const auto dir = test::scratch_dir("multi_device_launches");
    std::vector<std::string> args = {cornell(),
                                     "--width",
                                     "40",
                                     "--height",
                                     "36",
                                     "--spp",
                                     "8",
                                     "--device",
                                     "0:0,0:1",
                                     "-o",
                                     (dir / "x.exr").string(),
                                     "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    reset_device_call_counts();
    EXPECT_EQ(run_render_command(args), 0);
    uint64_t launches = 0;
    for (const auto& [name, site] : device_call_sites()) {
        if (site.api == "clEnqueueNDRangeKernel") {
            launches += site.calls;
        }
    }
    return launches;
}

// In this process (the fault injection is in-process): the path tracer's 20th kernel launch; the
// irradiance cache's 7th with one cache level (after the loop probe on each device,
// host/device/device_features.h, then the G-buffer, its tile depths, the first placement pass's
// coverage query and selection on the first device: the first record range's hemisphere cells,
// in the split) and its last (the final pass's, shared by the devices); the
// decomposition's last with the path source (its pass 2, shared by the devices).
TEST(MultiDevice, ADeviceThatFailsMidRenderStopsTheRenderNamingIt) {
    setenv("POCL_DEVICES", "pthread pthread", 1);  // before this process's first OpenCL call
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    expect_failing_device_named("multi_device_fault", {}, 20);
    const std::vector<std::string> ic = {"--method", "ic", "--ic-rays", "256"};
    const uint64_t launches = kernel_launches(ic);
    ASSERT_GT(launches, 2u);
    expect_failing_device_named("multi_device_fault_ic_final", ic, launches);
    std::vector<std::string> one_level = ic;
    one_level.insert(one_level.end(), {"--ic-bounces", "1"});
    expect_failing_device_named("multi_device_fault_ic_records", one_level, 7);
    const std::vector<std::string> decomposition = {"--method", "decomposition", "--decomp-source",
                                                    "path",     "--alpha",       "3%"};
    const uint64_t decomposition_launches = kernel_launches(decomposition);
    ASSERT_GT(decomposition_launches, 2u);
    expect_failing_device_named("multi_device_fault_decomposition", decomposition,
                                decomposition_launches);
}

// Mesa's rusticl beside PoCL (RUSTICL_ENABLE=llvmpipe): two platforms, as a CPU and a GPU would
// be. Whether its device is listed as 1:0.
bool rusticl_beside_pocl() {
    const test::CommandResult result = test::run_radcache({"devices"}, {"RUSTICL_ENABLE=llvmpipe"});
    return result.exit_code == 0 && result.output.find("\n1:0    rusticl") != std::string::npos;
}

// The path tracer over PoCL and rusticl (--device all): both devices get pixels, and the image's
// mean per channel is within 5 standard errors (from its stddev layer) of PoCL's alone: the two
// compilers may round differently, so bitwise equality is asked of each implementation alone.
TEST(TwoPlatforms, PathTracerOverPoclAndRusticlAgreesWithOneDevice) {
    if (!rusticl_beside_pocl()) {
        GTEST_SKIP() << "rusticl is not installed (mesa-opencl-icd)";
    }
    const auto dir = test::scratch_dir("two_platforms_pt");
    std::vector<nlohmann::json> stats;
    for (const std::string devices : {"0:0", "all"}) {
        const test::CommandResult result = test::run_radcache(
            {"render", cornell(), "--width", "40", "--height", "36", "--spp", "16", "--device",
             devices, "-o", (dir / (devices + ".exr")).string(), "--stats",
             (dir / (devices + ".json")).string(), "--quiet", "--allow-loop-cap"},
            {"RUSTICL_ENABLE=llvmpipe"});
        ASSERT_EQ(result.exit_code, 0) << result.output;
        stats.push_back(nlohmann::json::parse(read_file(dir / (devices + ".json"))));
    }
    const nlohmann::json& devices = stats[1].at("frames").at(0).at("devices");
    ASSERT_EQ(devices.size(), 2u);
    for (const nlohmann::json& d : devices) {
        EXPECT_GT(d.at("pixels").get<size_t>(), 0u) << d.dump();
    }
    const Image one = read_image(dir / "0:0.exr");
    const Image both = read_image(dir / "all.exr");
    const Image beauty_one = select_layers(one, {"beauty"});
    const Image beauty_both = select_layers(both, {"beauty"});
    const Image stddev = select_layers(one, {"stddev"});
    const double pixels = static_cast<double>(one.width) * one.height;
    for (int c = 0; c < 3; ++c) {
        double mean_one = 0.0, mean_both = 0.0, variance = 0.0;
        for (int y = 0; y < one.height; ++y) {
            for (int x = 0; x < one.width; ++x) {
                mean_one += beauty_one.at(x, y, c) / pixels;
                mean_both += beauty_both.at(x, y, c) / pixels;
                variance += std::pow(stddev.at(x, y, c), 2) / 16.0 / (pixels * pixels);
            }
        }
        EXPECT_LE(std::abs(mean_both - mean_one), 5.0 * std::sqrt(2.0 * variance))
            << "channel " << c << ": " << mean_both << " against " << mean_one;
    }
}

// A fault on either platform's device mid-render stops the render naming that device, with no
// output (in this process: the 20th kernel launch, on whichever device made it).
TEST(TwoPlatforms, ADeviceThatFailsMidRenderStopsTheRenderNamingIt) {
    setenv("RUSTICL_ENABLE", "llvmpipe", 1);  // before this process's first OpenCL call
    if (!rusticl_beside_pocl()) {
        GTEST_SKIP() << "rusticl is not installed (mesa-opencl-icd)";
    }
    expect_failing_device_named("two_platforms_fault", {"--allow-loop-cap"}, 20, "0:0,1:0");
}

// rusticl's llvmpipe ends a work item's loops after 65535 iterations in all (the loop probe,
// host/device/device_features.h): a render there, alone or beside PoCL, is refused before any
// work with one line naming the device and the cap, and writes nothing.
TEST(TwoPlatforms, ADeviceThatEndsLoopsEarlyIsRefusedByName) {
    if (!rusticl_beside_pocl()) {
        GTEST_SKIP() << "rusticl is not installed (mesa-opencl-icd)";
    }
    const auto dir = test::scratch_dir("two_platforms_loop_cap");
    for (const std::string devices : {"1:0", "all"}) {
        const auto out = dir / "x.exr";
        const test::CommandResult result =
            test::run_radcache({"render", cornell(), "--width", "8", "--height", "8", "--spp", "1",
                                "--device", devices, "-o", out.string(), "--quiet"},
                               {"RUSTICL_ENABLE=llvmpipe", "RADCACHE_ALLOW_LOOP_CAP="});
        EXPECT_EQ(result.exit_code, 2) << devices << ": " << result.output;
        EXPECT_NE(result.output.find("1:0 (llvmpipe"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("after 65535 iterations"), std::string::npos) << result.output;
        EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << devices;
    }
}

// A method that does not declare that its work splits (every registered one does today) is
// refused a device list by name, with exit status 2, before any context is opened; one device is
// opened for it as for any method.
TEST(MultiDevice, AMethodThatDoesNotSplitIsRefusedSeveralDevices) {
    setenv("POCL_DEVICES", "pthread pthread", 1);  // before this process's first OpenCL call
    if (!tests_run_on_pocl()) {
        GTEST_SKIP() << kNotOnPocl;
    }
    if (!two_devices()) {
        GTEST_SKIP() << "PoCL does not expose two devices here";
    }
    struct OneDeviceMethod final : Method {
        FrameResult render_frame(const FrameScene&, const FrameHooks&) override { return {}; }
        std::vector<ProgramRequest> programs() const override { return {}; }
        DeviceMemoryNeed device_memory_need(const Scene&, const DeviceInfo&) const override {
            return {};
        }
    };
    const OneDeviceMethod method;
    ContextOptions options;
    options.device_spec = "0:0,0:1";
    try {
        open_render_devices(options, method, "one-device");
        ADD_FAILURE() << "two devices were opened for a method that renders on one";
    } catch (const Error& error) {
        EXPECT_EQ(error.exit_code(), kExitUsage);
        EXPECT_NE(std::string(error.what()).find("--method one-device renders on one"),
                  std::string::npos)
            << error.what();
    }
    options.device_spec = "0:1";
    EXPECT_EQ(open_render_devices(options, method, "one-device").size(), 1u);
}

}  // namespace
}  // namespace rc
