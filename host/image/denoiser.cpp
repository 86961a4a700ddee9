#include "image/denoiser.h"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <type_traits>
#include <vector>

#include "util/error.h"
#include "util/timing.h"

namespace rc {
namespace {

// OIDN 2's C API, as its header oidn.h declares it (the values of its enums, the signatures of
// the functions radcache calls); the handles are opaque pointers.
using OidnDevice = void*;
using OidnFilter = void*;
constexpr int kOidnDeviceTypeCpu = 1;
constexpr int kOidnFormatFloat3 = 3;
constexpr int kOidnErrorNone = 0;
constexpr const char* kLibraryName = "libOpenImageDenoise.so.2";
constexpr const char* kLibraryVariable = "RADCACHE_OIDN_LIBRARY";

// The copy of the library pyoidn ships, as python3 finds the package (without importing it);
// empty with a reason when there is none.
std::string pyoidn_library(std::string* why) {
    const char* command =
        "python3 -c \"import importlib.util as u, os; s = u.find_spec('pyoidn'); "
        "print(os.path.join(os.path.dirname(s.origin), 'oidn', 'lib', "
        "'libOpenImageDenoise.so.2') if s else '')\" 2>/dev/null";
    FILE* pipe = popen(command, "r");
    if (pipe == nullptr) {
        *why = "python3 could not be started";
        return "";
    }
    std::array<char, 4096> line{};
    std::string path;
    while (std::fgets(line.data(), static_cast<int>(line.size()), pipe) != nullptr) {
        path += line.data();
    }
    const int status = pclose(pipe);
    while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) {
        path.pop_back();
    }
    if (status != 0) {
        *why = "python3 not found or failed";
    } else if (path.empty()) {
        *why = "python3 has no pyoidn package (pip install pyoidn)";
    }
    return path;
}

}  // namespace

struct Denoiser::Api {
    void* handle = nullptr;
    OidnDevice device = nullptr;
    OidnDevice (*new_device)(int) = nullptr;
    void (*commit_device)(OidnDevice) = nullptr;
    void (*release_device)(OidnDevice) = nullptr;
    int (*device_error)(OidnDevice, const char**) = nullptr;
    OidnFilter (*new_filter)(OidnDevice, const char*) = nullptr;
    void (*shared_image)(OidnFilter, const char*, void*, int, size_t, size_t, size_t, size_t,
                         size_t) = nullptr;
    void (*filter_bool)(OidnFilter, const char*, bool) = nullptr;
    void (*filter_int)(OidnFilter, const char*, int) = nullptr;
    void (*commit_filter)(OidnFilter) = nullptr;
    void (*execute_filter)(OidnFilter) = nullptr;
    void (*release_filter)(OidnFilter) = nullptr;

    // Resolves every function; false, with the first missing name in *why, otherwise.
    bool resolve(std::string* why) {
        const auto bind = [&](auto& function, const char* name) {
            void* symbol = dlsym(handle, name);
            if (symbol == nullptr && why->empty()) {
                *why = std::string("it has no ") + name + " (not OIDN 2)";
            }
            function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(symbol);
        };
        bind(new_device, "oidnNewDevice");
        bind(commit_device, "oidnCommitDevice");
        bind(release_device, "oidnReleaseDevice");
        bind(device_error, "oidnGetDeviceError");
        bind(new_filter, "oidnNewFilter");
        bind(shared_image, "oidnSetSharedFilterImage");
        bind(filter_bool, "oidnSetFilterBool");
        bind(filter_int, "oidnSetFilterInt");
        bind(commit_filter, "oidnCommitFilter");
        bind(execute_filter, "oidnExecuteFilter");
        bind(release_filter, "oidnReleaseFilter");
        return why->empty();
    }

    // Error with OIDN's message when its device reports one.
    void check(const std::string& step) const {
        const char* message = nullptr;
        if (device_error(device, &message) != kOidnErrorNone) {
            throw Error("--denoise: Open Image Denoise failed to " + step + ": " +
                        (message != nullptr ? message : "no message"));
        }
    }
};

int denoise_quality(const std::string& name) {
    if (name == "high") {
        return 6;  // OIDN_QUALITY_HIGH
    }
    if (name == "balanced") {
        return 5;
    }
    if (name == "fast") {
        return 4;
    }
    throw Error("--denoise-quality: expected high, balanced or fast, got '" + name + "'",
                kExitUsage);
}

std::unique_ptr<Denoiser> Denoiser::load(const std::string& library, int quality) {
    // The places to look, in order, each with what to call it in the error line.
    std::vector<std::pair<std::string, std::string>> candidates;
    if (!library.empty()) {
        candidates.push_back({library, "--denoise-library " + library});
    } else {
        const char* variable = std::getenv(kLibraryVariable);
        if (variable != nullptr && *variable != '\0') {
            candidates.push_back({variable, std::string("$") + kLibraryVariable + "=" + variable});
        } else {
            candidates.push_back(
                {kLibraryName, std::string(kLibraryName) + " on the loader's path"});
            std::string why;
            const std::string pyoidn = pyoidn_library(&why);
            candidates.push_back(pyoidn.empty() ? std::pair{std::string(), why}
                                                : std::pair{pyoidn, "pyoidn's " + pyoidn});
        }
    }
    std::string tried;
    std::unique_ptr<Denoiser> denoiser(new Denoiser());
    denoiser->api_ = std::make_unique<Api>();
    Api& api = *denoiser->api_;
    for (const auto& [path, name] : candidates) {
        std::string why;
        if (!path.empty()) {
            dlerror();
            api.handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (api.handle == nullptr) {
                const char* message = dlerror();
                why = message != nullptr ? message : "cannot be loaded";
            } else if (api.resolve(&why)) {
                denoiser->path_ = path;
                break;
            } else {
                dlclose(api.handle);
                api.handle = nullptr;
            }
        }
        tried += (tried.empty() ? "" : "; ") + (path.empty() ? name : name + ": " + why);
    }
    if (api.handle == nullptr) {
        throw Error("--denoise: Open Image Denoise not found (" + tried +
                        "); pip install pyoidn, or name the library with --denoise-library",
                    kExitUsage);
    }
    api.device = api.new_device(kOidnDeviceTypeCpu);
    if (api.device == nullptr) {
        throw Error("--denoise: Open Image Denoise (" + denoiser->path_ +
                    ") could not make a CPU device");
    }
    api.commit_device(api.device);
    api.check("start its CPU device");
    denoiser->quality_ = quality;
    return denoiser;
}

Denoiser::~Denoiser() {
    if (api_ && api_->device != nullptr) {
        api_->release_device(api_->device);
    }
    // The library stays loaded: OIDN's thread pool may outlive the device briefly.
}

void Denoiser::run(const float* colour, const float* albedo, const float* normal, float* output,
                   int width, int height) const {
    const Api& api = *api_;
    OidnFilter filter = api.new_filter(api.device, "RT");
    api.check("make its RT filter");
    const auto image = [&](const char* name, const float* pixels) {
        api.shared_image(filter, name, const_cast<float*>(pixels), kOidnFormatFloat3, width, height,
                         0, 0, 0);
    };
    image("color", colour);
    image("albedo", albedo);
    image("normal", normal);
    image("output", output);
    api.filter_bool(filter, "hdr", true);
    api.filter_int(filter, "quality", quality_);
    api.commit_filter(filter);
    api.execute_filter(filter);
    const char* message = nullptr;
    const bool failed = api.device_error(api.device, &message) != kOidnErrorNone;
    api.release_filter(filter);
    if (failed) {
        throw Error(std::string("--denoise: Open Image Denoise failed to filter the image: ") +
                    (message != nullptr ? message : "no message"));
    }
}

Image Denoiser::denoise(const Image& image) const {
    // The R, G, B channels of a layer ("" for the beauty), as indices into the image.
    const auto layer = [&](const std::string& prefix) {
        std::array<int, 3> index{-1, -1, -1};
        for (int c = 0; c < image.channels; ++c) {
            for (int k = 0; k < 3; ++k) {
                if (image.channel_names[c] == prefix + "RGB"[k]) {
                    index[k] = c;
                }
            }
        }
        if (index[0] < 0 || index[1] < 0 || index[2] < 0) {
            throw Error(
                "--denoise: the image has no " +
                (prefix.empty() ? std::string("beauty") : prefix.substr(0, prefix.size() - 1)) +
                " layer (R, G, B) to denoise with");
        }
        return index;
    };
    const std::array<int, 3> beauty = layer("");
    const std::array<int, 3> albedo = layer("albedo.");
    const std::array<int, 3> normal = layer("normal.");
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    // Interleaved float3 copies, non-finite values read as 0 and the beauty as non-negative.
    const auto copy = [&](const std::array<int, 3>& index, bool beauty_channel) {
        std::vector<float> out(pixels * 3);
        for (size_t p = 0; p < pixels; ++p) {
            for (int k = 0; k < 3; ++k) {
                const float v = image.pixels[p * image.channels + index[k]];
                out[p * 3 + k] = !std::isfinite(v) ? 0.0f : beauty_channel ? std::max(v, 0.0f) : v;
            }
        }
        return out;
    };
    const std::vector<float> colour = copy(beauty, true);
    const std::vector<float> albedo_pixels = copy(albedo, false);
    const std::vector<float> normal_pixels = copy(normal, false);
    std::vector<float> denoised(pixels * 3, 0.0f);
    run(colour.data(), albedo_pixels.data(), normal_pixels.data(), denoised.data(), image.width,
        image.height);

    // The output: the image (its windows and attributes kept) with beauty_noisy inserted after
    // the beauty's last channel and the beauty's channels denoised (they lie before the insert).
    const size_t insert = static_cast<size_t>(std::max({beauty[0], beauty[1], beauty[2]})) + 1;
    Image out = image;
    out.channels = image.channels + 3;
    out.channel_names.insert(out.channel_names.begin() + static_cast<std::ptrdiff_t>(insert),
                             {"beauty_noisy.R", "beauty_noisy.G", "beauty_noisy.B"});
    out.pixels.resize(pixels * out.channels);
    for (size_t p = 0; p < pixels; ++p) {
        const float* in = &image.pixels[p * image.channels];
        float* to = &out.pixels[p * out.channels];
        std::copy(in, in + insert, to);
        std::copy(in + insert, in + image.channels, to + insert + 3);
        for (int k = 0; k < 3; ++k) {
            to[insert + k] = in[beauty[k]];
            to[beauty[k]] = denoised[p * 3 + k];
        }
    }
    return out;
}

void Denoiser::calibrate() {
    // t(n) = setup + n * per_pixel, from two sizes after a first run that sets OIDN up.
    const auto seconds = [&](int side) {
        const size_t n = static_cast<size_t>(side) * side * 3;
        std::vector<float> colour(n, 0.5f), albedo(n, 0.5f), normal(n, 0.0f), output(n);
        for (size_t i = 2; i < n; i += 3) {
            normal[i] = 1.0f;
        }
        const auto start = SteadyClock::now();
        run(colour.data(), albedo.data(), normal.data(), output.data(), side, side);
        return seconds_since(start);
    };
    seconds(32);
    const double small = seconds(64);
    const double large = seconds(128);
    seconds_per_pixel_ = std::max(0.0, (large - small) / (128.0 * 128.0 - 64.0 * 64.0));
    setup_seconds_ = std::max(0.0, small - seconds_per_pixel_ * 64.0 * 64.0);
}

double Denoiser::predicted_seconds(int width, int height) {
    if (seconds_per_pixel_ == 0.0 && setup_seconds_ == 0.0) {
        calibrate();
    }
    return setup_seconds_ + seconds_per_pixel_ * static_cast<double>(width) * height;
}

}  // namespace rc
