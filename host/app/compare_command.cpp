// `radcache compare TEST REF`: an image's error against a reference (DESIGN.md §7).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "image/image.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "util/cli.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {

int run_compare_command(const std::vector<std::string>& args) {
    const std::vector<OptionSpec> specs = {
        {"--aov", "", "NAME", "layer to compare (default beauty: the R, G, B channels)"},
        {"--json", "", "FILE", "also write the figures as JSON"},
        {"--error-image", "", "FILE",
         "write a false-colour image of each pixel's relMSE (.png, .exr, .hdr, .pfm)"},
    };
    const ParsedArguments arguments = parse_arguments("radcache compare", args, specs);
    if (arguments.has("--help")) {
        std::cout << format_help("radcache compare TEST REF [options]",
                                 "Error of TEST against REF over one layer: RMSE, relMSE "
                                 "((v-r)^2/(r^2+0.01) averaged over pixels and channels), PSNR "
                                 "(peak 1), per-channel means and the largest difference. The "
                                 "error image maps log10 of a pixel's relMSE from -5 (black) "
                                 "through blue, magenta, red and yellow to 0 (white).",
                                 specs);
        return 0;
    }
    if (arguments.positionals().size() != 2) {
        throw Error("radcache compare needs TEST and REF images (see radcache compare --help)",
                    kExitUsage);
    }
    const std::string test_path = arguments.positionals()[0];
    const std::string reference_path = arguments.positionals()[1];
    const std::string layer = arguments.value("--aov", "beauty");
    const std::filesystem::path json_path = arguments.value("--json");
    if (!json_path.empty()) {
        check_writable_parent(json_path, "--json");
    }
    const std::filesystem::path error_image_path = arguments.value("--error-image");
    if (!error_image_path.empty()) {
        check_output_path(error_image_path);
    }
    const Image test = select_layers(read_image(test_path), {layer});
    const Image reference = select_layers(read_image(reference_path), {layer});
    const ImageError e = image_error(test, reference, test_path);

    char line[256];
    std::snprintf(line, sizeof(line), "rmse %.6g  relmse %.6g  psnr %.3f dB\n", e.rmse, e.relmse,
                  e.psnr);
    std::cout << line;
    for (size_t c = 0; c < e.channels.size(); ++c) {
        std::snprintf(line, sizeof(line), "mean %-12s %.6g (reference %.6g)\n",
                      e.channels[c].c_str(), e.test_means[c], e.reference_means[c]);
        std::cout << line;
    }
    std::snprintf(line, sizeof(line), "max |difference| %.6g at pixel (%d, %d) channel %s\n",
                  e.max_error, e.max_x, e.max_y,
                  e.channels.empty() ? "" : e.channels[e.max_channel].c_str());
    std::cout << line;
    if (!error_image_path.empty()) {
        write_image(error_image_path, error_image(test, reference, test_path));
        std::snprintf(line, sizeof(line),
                      "error image %s: log10 relMSE per pixel, %g black to %g white\n",
                      error_image_path.string().c_str(), kErrorImageLog10Min, kErrorImageLog10Max);
        std::cout << line;
    }
    if (!json_path.empty()) {
        nlohmann::json j;
        j["test"] = test_path;
        j["reference"] = reference_path;
        j["aov"] = layer;
        j["rmse"] = e.rmse;
        j["relmse"] = e.relmse;
        j["psnr"] = std::isfinite(e.psnr) ? nlohmann::json(e.psnr) : nlohmann::json(nullptr);
        j["channels"] = e.channels;
        j["test_means"] = e.test_means;
        j["reference_means"] = e.reference_means;
        j["max_error"] = {{"value", e.max_error},
                          {"pixel", {e.max_x, e.max_y}},
                          {"channel", e.channels.empty() ? "" : e.channels[e.max_channel]}};
        if (!error_image_path.empty()) {
            j["error_image"] = error_image_path.string();
        }
        write_file_atomically(json_path, j.dump(2) + "\n");
    }
    return 0;
}

}  // namespace rc
