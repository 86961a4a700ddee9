#include "app/denoise_options.h"

#include "util/error.h"

namespace rc {

std::vector<OptionSpec> denoise_option_specs() {
    return {
        {"--denoise", "", "",
         "denoise the beauty with Intel Open Image Denoise before the image is written (its RT "
         "filter, with the albedo and normal layers as auxiliaries; the noisy beauty kept as the "
         "layer beauty_noisy); render: each frame, its predicted time taken out of --time "
         "(docs/denoising.md)"},
        OptionSpec{"--denoise-quality", "", "NAME",
                   "--denoise: the filter's quality, high, balanced or fast (default high)"}
            .one_of({"high", "balanced", "fast"}),
        {"--denoise-library", "", "FILE",
         "--denoise: the Open Image Denoise library to load (default: $RADCACHE_OIDN_LIBRARY, "
         "else libOpenImageDenoise.so.2 on the loader's path, else the copy in pip's pyoidn "
         "package)"},
    };
}

DenoiseRequest read_denoise_request(const ParsedArguments& arguments) {
    DenoiseRequest request;
    request.given = arguments.has("--denoise");
    for (const char* option : {"--denoise-quality", "--denoise-library"}) {
        if (!request.given && arguments.has(option)) {
            throw Error(std::string(option) + " needs --denoise", kExitUsage);
        }
    }
    request.quality = arguments.value("--denoise-quality", "high");
    denoise_quality(request.quality);  // checked before any work
    request.library = arguments.value("--denoise-library");
    return request;
}

std::unique_ptr<Denoiser> open_denoiser(const DenoiseRequest& request) {
    if (!request.given) {
        return nullptr;
    }
    return Denoiser::load(request.library, denoise_quality(request.quality));
}

}  // namespace rc
