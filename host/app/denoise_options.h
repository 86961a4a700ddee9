// The options of --denoise (image/denoiser.h), which render and merge share: declared once here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image/denoiser.h"
#include "util/cli.h"

namespace rc {

std::vector<OptionSpec> denoise_option_specs();

struct DenoiseRequest {
    bool given = false;   // --denoise
    std::string quality;  // high, balanced or fast
    std::string library;  // empty: found as image/denoiser.h says
};

// --denoise, --denoise-quality, --denoise-library; Error (exit status 2) naming an option given
// without --denoise.
DenoiseRequest read_denoise_request(const ParsedArguments& arguments);

// The denoiser the request asks for (null when it asks for none); Error naming where the
// library was looked for when it cannot be loaded.
std::unique_ptr<Denoiser> open_denoiser(const DenoiseRequest& request);

}  // namespace rc
