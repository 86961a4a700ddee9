#include "test_support.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <map>
#include <memory>

#include "image/image_io.h"
#include "scene/scene_loader.h"
#include "util/error.h"

namespace rc::test {

ContextOptions default_context_options() {
    ContextOptions options;
    options.cache_dir = RADCACHE_TEST_CACHE_DIR;
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

Scene load_cornell_box() { return load_scene(source_dir() / "scenes/cornell-box/scene.json"); }

Material pure_phong(float exponent) {
    Material m;
    m.name = "phong " + std::to_string(static_cast<int>(exponent));
    m.kind = MaterialKind::kPhong;
    m.diffuse = glm::vec3(0.0f);
    m.specular = glm::vec3(1.0f);
    m.exponent = exponent;
    return m;
}

Image box_filtered(const Image& image, int factor) {
    Image out(image.width / factor, image.height / factor, image.channels);
    out.channel_names = image.channel_names;
    const double weight = 1.0 / (static_cast<double>(factor) * factor);
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            for (int c = 0; c < image.channels; ++c) {
                double sum = 0.0;
                for (int j = 0; j < factor; ++j) {
                    for (int i = 0; i < factor; ++i) {
                        sum += image.at(factor * x + i, factor * y + j, c);
                    }
                }
                out.at(x, y, c) = static_cast<float>(sum * weight);
            }
        }
    }
    return out;
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

std::filesystem::path scratch_dir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(RADCACHE_TEST_SCRATCH_DIR) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
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
