#include "test_support.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>

#include "image/image_io.h"
#include "scene/scene_loader.h"
#include "test_device.h"
#include "util/error.h"

namespace rc::test {

ContextOptions default_context_options() {
    ContextOptions options;
    options.cache_dir = RADCACHE_TEST_CACHE_DIR;
    options.device_spec = test_device_spec();
    return options;
}

ContextOptions chunked_context_options(size_t local_size, size_t max_chunk_items) {
    ContextOptions options = default_context_options();
    options.local_size = local_size;
    options.max_chunk_items = max_chunk_items;
    return options;
}

Context& shared_context() {
    static Context context(default_context_options());
    return context;
}

Context& layout_context(BvhLayout layout) {
    static std::map<BvhLayout, std::unique_ptr<Context>> contexts;
    std::unique_ptr<Context>& context = contexts[layout];
    if (!context) {
        ContextOptions options = default_context_options();
        options.bvh_layout = layout;
        context = std::make_unique<Context>(options);
    }
    return *context;
}

std::filesystem::path source_dir() { return RADCACHE_SOURCE_DIR; }

std::filesystem::path radcache_executable() { return RADCACHE_EXECUTABLE; }

std::filesystem::path kernel_cache_dir() { return RADCACHE_TEST_CACHE_DIR; }

Scene load_cornell_box() { return load_scene(source_dir() / "scenes/cornell-box/scene.json"); }

Scene load_scene_at_frame(const std::filesystem::path& path, int frame) {
    Scene scene = load_scene(path);
    scene.set_frame(frame);
    return scene;
}

Scene floor_and_ceiling(float half_size, const std::string& scratch) {
    const auto dir = scratch_dir(scratch);
    const std::string scale = std::to_string(half_size);
    std::ofstream(dir / "scene.json")
        << R"({
        "camera": {"position": [0, 0.9, 0], "look_at": [0, 0, 0.01], "up": [0, 0, 1],
                   "fov": 60, "resolution": [16, 16]},
        "materials": {"white": {"type": "diffuse", "reflectance": 0.5}},
        "shapes": [
            {"type": "rectangle", "material": "white",
             "transform": [{"scale": )"
        << scale << R"(}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]},
            {"type": "rectangle", "material": "white",
             "transform": [{"scale": )"
        << scale << R"(}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 1, 0]}]},
            {"type": "rectangle", "material": "white", "emitter": {"type": "area", "radiance": 5},
             "transform": [{"scale": 0.2}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                           {"translate": [0, 0.999, 0]}]}
        ]
    })";
    return load_scene(dir / "scene.json");
}

Scene furnace_box(const std::string& scratch) {
    const auto dir = scratch_dir(scratch);
    const std::string rho = std::to_string(kFurnaceReflectance);
    const std::string emission = std::to_string(kFurnaceEmission);
    std::ofstream(dir / "scene.json") << R"({
        "camera": {"position": [0.7, 0.4, -0.8], "look_at": [-0.3, -0.7, 0.5], "up": [0, 1, 0],
                   "fov": 100, "resolution": [16, 16]},
        "materials": {"grey": {"type": "diffuse", "reflectance": )"
                                      << rho << R"(}},
        "shapes": [
            {"type": "cube", "material": "grey", "flip_normals": true,
             "emitter": {"type": "area", "radiance": )"
                                      << emission << R"(}},
            {"type": "cube", "material": "grey", "emitter": {"type": "area", "radiance": )"
                                      << emission << R"(},
             "transform": [{"scale": 0.3}, {"translate": [-0.2, -0.6, 0.2]}]}
        ]
    })";
    return load_scene(dir / "scene.json");
}

Material pure_phong(float exponent) {
    Material m;
    m.name = "phong " + std::to_string(static_cast<int>(exponent));
    m.kind = MaterialKind::kPhong;
    m.diffuse = glm::vec3(0.0f);
    m.specular = glm::vec3(1.0f);
    m.exponent = exponent;
    return m;
}

Image scene_reference(const std::string& scene, const std::string& layer, int size) {
    const Image full =
        select_layers(read_image(source_dir() / "scenes" / scene / "reference.exr"), {layer});
    if (full.width != full.height || full.width % size != 0) {
        throw Error("the " + scene + " reference (" + std::to_string(full.width) + " x " +
                    std::to_string(full.height) + ") is not a multiple of " + std::to_string(size) +
                    " x " + std::to_string(size));
    }
    return box_filtered(full, full.width / size);
}

Image cornell_reference(const std::string& layer, int size) {
    return scene_reference("cornell-box", layer, size);
}

DeviceFrame::DeviceFrame(Scene loaded, Context& device)
    : context(device),
      scene(std::move(loaded)),
      bvh(build_bvh(scene.mesh, device.bvh_layout())),
      device_bvh(context, bvh),
      device_scene(context, scene) {}

// The running test's own folder: ctest runs each test in its own process, in parallel, so two
// tests that name the same scratch must not share (and remove) one directory. Named by ten hex
// digits of a hash of "Suite.Name", short so that the paths the tests' error messages quote stay
// within the length radcache quotes whole.
static std::filesystem::path running_test_folder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    if (info == nullptr) {
        return "outside-tests";
    }
    const std::string name = std::string(info->test_suite_name()) + "." + info->name();
    uint64_t hash = 14695981039346656037ull;  // FNV-1a
    for (unsigned char c : name) {
        hash = (hash ^ c) * 1099511628211ull;
    }
    char folder[16];
    std::snprintf(folder, sizeof folder, "%010llx",
                  static_cast<unsigned long long>(hash & 0xffffffffffull));
    return folder;
}

std::filesystem::path scratch_dir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(RADCACHE_TEST_SCRATCH_DIR) / running_test_folder() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

bool declares(const MethodEntry& method, const std::string& option) {
    return std::any_of(method.options.begin(), method.options.end(),
                       [&](const OptionSpec& spec) { return spec.name == option; });
}

std::vector<std::string> quick_method_options(const MethodEntry& method,
                                              const std::vector<std::string>& options) {
    const auto given = [&](const std::string& option) {
        return std::find(options.begin(), options.end(), option) != options.end();
    };
    // The grid's options are refused where no grid is made: without --ic-ivg where the grid is
    // optional, with a --decomp-source other than the grid.
    const auto source = std::find(options.begin(), options.end(), "--decomp-source");
    const bool grid =
        (!declares(method, "--ic-ivg") || given("--ic-ivg")) &&
        (source == options.end() || source + 1 == options.end() || source[1] == "grid");
    std::vector<std::string> quick;
    const auto turn_down = [&](const std::string& option, const std::string& value) {
        if (declares(method, option) && !given(option)) {
            quick.insert(quick.end(), {option, value});
        }
    };
    turn_down("--ic-rays", "16");
    turn_down("--rc-rays", "16");
    turn_down("--sdrc-samples", "16");
    turn_down("--gather-rays", "2");
    // Fewer split triangles: every launch within the first chunk (2^16 items), so a render makes
    // the same device calls however long they take (the device-fault sweep counts on it).
    turn_down("--alpha", "4%");
    if (grid) {
        turn_down("--photons", "4000");
    }
    return quick;
}

namespace {

std::string shell_quote(const std::string& word) {
    std::string quoted = "'";
    for (char c : word) {
        if (c == '\'') {
            quoted += "'\\''";
        } else {
            quoted += c;
        }
    }
    return quoted + "'";
}

}  // namespace

CommandResult run_radcache(const std::vector<std::string>& args,
                           const std::vector<std::string>& environment) {
    std::string command = "env RADCACHE_CACHE_DIR=" + shell_quote(RADCACHE_TEST_CACHE_DIR);
    // The tests' device, unless `environment` names another; rendered on even where it ends
    // loops early (Mesa's llvmpipe), so that the tests' own bounds judge what it computes.
    if (const std::string device = test_device_spec(); !device.empty()) {
        command += " " + shell_quote("RADCACHE_DEVICE=" + device) + " RADCACHE_ALLOW_LOOP_CAP=1";
    }
    for (const std::string& assignment : environment) {
        command += " " + shell_quote(assignment);
    }
    command += " " + shell_quote(radcache_executable().string());
    for (const std::string& arg : args) {
        command += " " + shell_quote(arg);
    }
    command += " 2>&1";
    CommandResult result;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return result;
    }
    std::array<char, 4096> buffer;
    size_t got = 0;
    while ((got = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
        result.output.append(buffer.data(), got);
    }
    const int status = ::pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

}  // namespace rc::test
