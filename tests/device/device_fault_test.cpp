// Device faults: every OpenCL call site that a small render of each registered method
// reaches is made to fail in turn (host/device/fault_injection.h), at its first call and at its
// last. Each failure must name the call and the error in one line, end the render with exit
// status 1, leave no output file (nor a temporary) behind, and release every OpenCL object it
// created. The only faults a render survives are those of a kernel cache entry, which is rebuilt
// from source.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

#include "app/commands.h"
#include "device/cl_error.h"
#include "device/fault_injection.h"
#include "methods/registry.h"
#include "scratch_files.h"
#include "test_support.h"
#include "util/error.h"
#include "util/log.h"

namespace rc {
namespace {

struct SmallRender {
    std::string name;  // of the test case
    std::string method;
    std::string scene;                 // under scenes/, or "DIR/file" for one written here
    std::vector<std::string> options;  // besides the output, the size and the stats
    std::vector<std::string> outputs;  // every file the render writes, in its directory
    bool last_calls = true;            // also fail each site's last call (not only its first)
    bool first_calls = true;
};

// A small glossy scene for radiance caching: one Phong material (each glossy material costs a
// BRDF table build of about a second on PoCL, and the sweep renders it some forty times).
const char* kPhongScene = R"({
    "camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "fov": 45, "resolution": [12, 10]},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.6},
                  "gloss": {"type": "phong", "diffuse": 0.3, "specular": 0.4, "exponent": 20}},
    "shapes": [
        {"type": "rectangle", "material": "white",
         "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 3}]},
        {"type": "cube", "material": "gloss", "transform": [{"scale": 0.5}, {"translate": [0, 0.5, 0]}]}
    ],
    "emitters": [{"type": "point", "position": [1, 3, 2], "intensity": 20}]
})";

// gtest's name for a case in test listings (CTest's test names).
void PrintTo(const SmallRender& render, std::ostream* out) { *out << render.name; }

struct RunResult {
    int exit_code = 0;
    std::string message;
};

// The render command in this process, as main() runs it (an Error's exit status and message).
RunResult run(const std::vector<std::string>& args) {
    try {
        return {run_render_command(args), ""};
    } catch (const Error& error) {
        return {error.exit_code(), error.what()};
    } catch (const std::exception& error) {
        return {kExitFailure, error.what()};
    }
}

std::vector<std::string> arguments(const SmallRender& render, const std::filesystem::path& dir,
                                   const std::filesystem::path& scene) {
    std::vector<std::string> args = {scene.string(),
                                     "-o",
                                     (dir / "out.exr").string(),
                                     "--method",
                                     render.method,
                                     "--width",
                                     "12",
                                     "--height",
                                     "10",
                                     "--spp",
                                     "1",
                                     "--quiet",
                                     "--stats",
                                     (dir / "stats.json").string()};
    for (const std::string& option : render.options) {
        args.push_back(option == "DIR" ? dir.string() : option);
    }
    for (std::string& arg : args) {
        if (arg.rfind("DIR/", 0) == 0) {
            arg = (dir / arg.substr(4)).string();
        }
    }
    return args;
}

void clear(const std::filesystem::path& dir) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        std::filesystem::remove_all(entry.path());
    }
}

// A kernel cache entry the driver refuses is rebuilt from source (program.cpp's
// try_build_from_binary): the only calls whose fault a render survives. With a warm kernel cache
// every program is built from its binary, so these are all the program calls the sweep reaches.
bool rebuilds_from_source(const DeviceCallSite& site, const std::vector<std::string>& args) {
    const bool cache = std::find(args.begin(), args.end(), "--no-kernel-cache") == args.end();
    return cache && (site.api == "clCreateProgramWithBinary" || site.api == "clBuildProgram");
}

// The OpenCL objects alive now, by kind (kinds with none left out).
std::map<std::string, long long> live_objects() {
    std::map<std::string, long long> live;
    for (const auto& [kind, count] : live_device_objects()) {
        if (count != 0) {
            live[kind] = count;
        }
    }
    return live;
}

class DeviceFaultSweep : public testing::TestWithParam<SmallRender> {};

TEST_P(DeviceFaultSweep, EveryCallSiteFailsCleanly) {
    const SmallRender& render = GetParam();
    const auto dir = test::scratch_dir("device_fault_" + render.name);
    std::filesystem::path scene = test::source_dir() / "scenes" / render.scene;
    if (render.scene == "phong") {
        scene = test::scratch_dir("device_fault_" + render.name + "_scene") / "scene.json";
        std::ofstream(scene) << kPhongScene;
    }
    const std::vector<std::string> args = arguments(render, dir, scene);
    const std::map<std::string, long long> objects_before = live_objects();

    // The fault-free render (twice: the second with a warm kernel cache): what it writes, and
    // the call sites it reaches.
    disarm_device_fault();
    ASSERT_EQ(run(args).exit_code, 0);
    clear(dir);
    reset_device_call_counts();
    const RunResult clean = run(args);
    ASSERT_EQ(clean.exit_code, 0) << clean.message;
    std::vector<std::string> expected = render.outputs;
    expected.insert(expected.end(), {"out.exr", "stats.json"});
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(test::file_names(dir), expected);
    const std::map<std::string, DeviceCallSite> sites = device_call_sites();
    ASSERT_GE(sites.size(), 10u);
    EXPECT_EQ(live_objects(), objects_before);

    // CL_OUT_OF_RESOURCES, CL_MEM_OBJECT_ALLOCATION_FAILURE, CL_OUT_OF_HOST_MEMORY in turn.
    const int kStatuses[] = {-5, -4, -6};
    size_t faults = 0;
    for (const auto& [key, site] : sites) {
        std::vector<uint64_t> calls;
        if (render.first_calls) {
            calls.push_back(site.first_call);
        }
        if (render.last_calls && (site.last_call != site.first_call || !render.first_calls) &&
            !rebuilds_from_source(site, args)) {
            calls.push_back(site.last_call);
        }
        for (const uint64_t nth : calls) {
            const int status = kStatuses[faults++ % 3];
            SCOPED_TRACE(key + ": call " + std::to_string(nth) + " of " + site.api +
                         " fails with " + cl_error_name(status));
            clear(dir);
            arm_device_fault(site.api, nth, status);
            const RunResult failed = run(args);
            EXPECT_TRUE(device_fault_fired());
            disarm_device_fault();
            EXPECT_EQ(live_objects(), objects_before) << "OpenCL objects leaked";
            if (rebuilds_from_source(site, args)) {
                EXPECT_EQ(failed.exit_code, 0) << failed.message;
                EXPECT_EQ(test::file_names(dir), expected);
                continue;
            }
            EXPECT_EQ(failed.exit_code, kExitFailure) << failed.message;
            EXPECT_NE(failed.message.find(site.api), std::string::npos) << failed.message;
            EXPECT_NE(failed.message.find(cl_error_name(status)), std::string::npos)
                << failed.message;
            EXPECT_EQ(failed.message.find('\n'), std::string::npos) << failed.message;
            EXPECT_EQ(test::file_names(dir), std::vector<std::string>{}) << "files left behind";
        }
    }
    std::cout << render.name << ": " << sites.size() << " call sites, " << faults
              << " faults injected:";
    for (const auto& [key, site] : sites) {
        std::cout << " " << key;
    }
    std::cout << "\n";
    set_quiet(false);
}

// Data loss: a run that fails after it has produced some of its outputs (here the
// irradiance cache, saved before the image is read back) leaves every old file as it was and no
// new one: the outputs are committed together at the end.
TEST(DeviceFault, AFailureAtTheEndKeepsEveryOldOutput) {
    const auto dir = test::scratch_dir("device_fault_old_outputs");
    const SmallRender render{
        "old",
        "ic",
        "cornell-box/scene.json",
        {"--ic-rays", "16", "--ic-bounces", "1", "--cache-out", "DIR/cache.rcc"},
        {}};
    const std::vector<std::string> args =
        arguments(render, dir, test::source_dir() / "scenes/cornell-box/scene.json");
    disarm_device_fault();
    reset_device_call_counts();
    ASSERT_EQ(run(args).exit_code, 0);
    uint64_t last_read = 0;
    for (const auto& [key, site] : device_call_sites()) {
        if (site.api == "clEnqueueReadBuffer") {
            last_read = std::max(last_read, site.last_call);
        }
    }
    ASSERT_GT(last_read, 1u);
    const std::vector<std::string> names = {"out.exr", "stats.json", "cache.rcc"};
    for (const std::string& name : names) {
        std::ofstream(dir / name) << "old " << name;
    }
    arm_device_fault("clEnqueueReadBuffer", last_read, -5);
    const RunResult failed = run(args);
    EXPECT_TRUE(device_fault_fired());
    disarm_device_fault();
    EXPECT_EQ(failed.exit_code, kExitFailure) << failed.message;
    for (const std::string& name : names) {
        std::ifstream in(dir / name);
        const std::string bytes((std::istreambuf_iterator<char>(in)), {});
        EXPECT_EQ(bytes, "old " + name);
    }
    EXPECT_EQ(test::file_names(dir),
              (std::vector<std::string>{"cache.rcc", "out.exr", "stats.json"}));
    set_quiet(false);
}

// The build log is read only after a build has failed (program.cpp's build_log): a kernel with a
// syntax error reaches those call sites, and a fault there leaves the build's own error, without
// the log.
TEST(DeviceFault, ABuildLogThatCannotBeReadLeavesTheBuildError) {
    const auto dir = test::scratch_dir("device_fault_build_log");
    const auto kernels = dir / "kernels";
    std::filesystem::copy(test::source_dir() / "kernels", kernels,
                          std::filesystem::copy_options::recursive);
    std::ofstream(kernels / "normals/normals.cl", std::ios::app) << "\nthis is not OpenCL C\n";
    const auto out = test::scratch_dir("device_fault_build_log_out");
    const std::vector<std::string> args = {
        (test::source_dir() / "scenes/cornell-box/scene.json").string(),
        "-o",
        (out / "out.png").string(),
        "--method",
        "normals",
        "--width",
        "8",
        "--height",
        "8",
        "--quiet",
        "--no-kernel-cache",
        "--kernel-dir",
        kernels.string()};
    disarm_device_fault();
    reset_device_call_counts();
    const RunResult failed_build = run(args);
    EXPECT_EQ(failed_build.exit_code, kExitFailure);
    EXPECT_NE(failed_build.message.find("clBuildProgram(normals/normals.cl) failed: "
                                        "CL_BUILD_PROGRAM_FAILURE"),
              std::string::npos)
        << failed_build.message;
    EXPECT_NE(failed_build.message.find("build log:\n"), std::string::npos);
    size_t log_sites = 0;
    for (const auto& [key, site] : device_call_sites()) {
        if (site.api != "clGetProgramBuildInfo") {
            continue;
        }
        ++log_sites;
        SCOPED_TRACE(key);
        arm_device_fault(site.api, site.first_call, -6);
        const RunResult failed = run(args);
        EXPECT_TRUE(device_fault_fired());
        disarm_device_fault();
        EXPECT_EQ(failed.exit_code, kExitFailure);
        EXPECT_NE(failed.message.find("clBuildProgram(normals/normals.cl) failed: "
                                      "CL_BUILD_PROGRAM_FAILURE on "),
                  std::string::npos)
            << failed.message;
        // No log: one line (with what the compiler printed on stderr, where it did).
        EXPECT_EQ(failed.message.find('\n'), std::string::npos) << "no log: " << failed.message;
        EXPECT_EQ(test::file_names(out), std::vector<std::string>{});
        EXPECT_EQ(live_objects(), (std::map<std::string, long long>{}));
    }
    EXPECT_EQ(log_sites, 2u);  // its size, then its text
}

SmallRender only_last_calls(SmallRender render) {
    render.name += "-last";
    render.first_calls = false;
    return render;
}

SmallRender only_first_calls(SmallRender render) {
    render.name += "-first";
    render.last_calls = false;
    return render;
}

// A small render of every registered method: its costliest knobs turned down, one cache level
// where it has levels, a method with a glossy layer on the Phong scene and in two cases (its
// first calls, its last calls), each of whose renders builds the scene's BRDF tables. Then the
// options that reach more call sites.
std::vector<SmallRender> small_renders() {
    std::vector<SmallRender> renders;
    for (const MethodEntry& method : method_registry()) {
        std::vector<std::string> options = test::quick_method_options(method);
        if (test::declares(method, "--ic-bounces")) {
            options.insert(options.end(), {"--ic-bounces", "1"});
        }
        const bool glossy = std::find(method.aovs.begin(), method.aovs.end(), "glossy-indirect") !=
                            method.aovs.end();
        const SmallRender render{
            method.name, method.name, glossy ? "phong" : "cornell-box/scene.json", options, {}};
        if (glossy) {
            renders.push_back(only_first_calls(render));
            renders.push_back(only_last_calls(render));
        } else if (method.name == "auto") {
            // auto's plan renders ic at its default 1024 rays per record (auto has no knob to turn
            // down), whose record launches fill the first chunk, so how many calls come last
            // depends on the launches' times: its first calls only (ic's cases reach the rest).
            renders.push_back(only_first_calls(render));
        } else {
            renders.push_back(render);
        }
    }
    // Every program built from source: the compiler's call sites.
    renders.push_back(
        {"normals-uncached", "normals", "cornell-box/scene.json", {"--no-kernel-cache"}, {}});
    // The record cache written.
    renders.push_back({"ic-cache-out",
                       "ic",
                       "cornell-box/scene.json",
                       {"--ic-rays", "16", "--ic-bounces", "1", "--cache-out", "DIR/cache.rcc"},
                       {"cache.rcc"}});
    // Temporal caching: the reprojection's kernels and buffers, placed on the moving sphere.
    renders.push_back({"ic-temporal",
                       "ic",
                       "moving-sphere/scene.json",
                       {"--ic-rays", "16", "--ic-bounces", "1", "--temporal", "--frames", "0:0"},
                       {}});
    // The grid written.
    renders.push_back({"ivg-grid-out",
                       "ivg",
                       "cornell-box/scene.json",
                       {"--photons", "2000", "--grid", "4x4x4", "--grid-out", "DIR/grid.rcg"},
                       {"grid.rcg"}});
    return renders;
}

INSTANTIATE_TEST_SUITE_P(Methods, DeviceFaultSweep, testing::ValuesIn(small_renders()),
                         [](const testing::TestParamInfo<SmallRender>& info) {
                             std::string name = info.param.name;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace rc
