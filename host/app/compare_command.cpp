// `radcache compare TEST REF`: an image's error against a reference (DESIGN.md §7).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "image/image.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "util/cli.h"
#include "util/error.h"
#include "util/file_io.h"

namespace rc {

namespace {

// What is known of the reference's own noise: its sample count and where it came from, or why the
// net figure is not reported.
struct ReferenceNoiseSource {
    double spp = 0.0;  // 0: unknown
    std::string from;  // "--reference-spp" or the stats file
    std::string note;  // why there is no net figure, when spp is 0
};

// The `spp` of a render's --stats JSON (or a reference.json), 0 when absent or unreadable.
double spp_of_stats_file(const std::filesystem::path& path) {
    std::ifstream in(path);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("spp") || !j["spp"].is_number()) {
        return 0.0;
    }
    const double spp = j["spp"].get<double>();
    return spp > 0.0 && std::isfinite(spp) ? spp : 0.0;
}

// Step 1 of the net figure: the reference's sample count, from --reference-spp or else from
// `<stem>.stats.json` (radcache render --stats) or `<stem>.json` (scenes/*/reference.json) beside
// the reference.
ReferenceNoiseSource find_reference_spp(const ParsedArguments& arguments,
                                        const std::filesystem::path& reference_path) {
    ReferenceNoiseSource source;
    if (arguments.has("--reference-spp")) {
        source.spp = static_cast<double>(
            arguments.integer("--reference-spp", 0, 1, std::numeric_limits<long long>::max()));
        source.from = "--reference-spp";
        return source;
    }
    const std::filesystem::path stem = reference_path.parent_path() / reference_path.stem();
    for (const char* suffix : {".stats.json", ".json"}) {
        const std::filesystem::path candidate = stem.string() + suffix;
        if (std::filesystem::is_regular_file(candidate)) {
            source.spp = spp_of_stats_file(candidate);
            if (source.spp > 0.0) {
                source.from = candidate.string();
                return source;
            }
        }
    }
    source.note = "the reference's sample count is unknown (pass --reference-spp N or put " +
                  stem.filename().string() + ".stats.json beside it)";
    return source;
}

// The reference's stddev channels in the order of the beauty channels `reference` holds
// ("stddev.R" for "R"); Error naming the reference when one is missing.
Image stddev_matching(const Image& reference_file, const Image& reference,
                      const std::string& reference_path) {
    const Image stddev = select_layers(reference_file, {"stddev"});
    Image matched(reference.width, reference.height, reference.channels);
    matched.channel_names.clear();
    for (int c = 0; c < reference.channels; ++c) {
        const std::string name = "stddev." + reference.channel_names[c];
        const auto found =
            std::find(stddev.channel_names.begin(), stddev.channel_names.end(), name);
        if (found == stddev.channel_names.end()) {
            throw Error(reference_path + ": no channel " + name, kExitUsage);
        }
        const int from = static_cast<int>(found - stddev.channel_names.begin());
        matched.channel_names.push_back(name);
        for (int y = 0; y < reference.height; ++y) {
            for (int x = 0; x < reference.width; ++x) {
                matched.at(x, y, c) = stddev.at(x, y, from);
            }
        }
    }
    return matched;
}

// Step 2: the error, net of the reference's noise where its stddev layer and spp are known.
// Error (exit 2) when --reference-spp asks for a net figure that cannot be had.
ImageError compare_images(const Image& test_file, const Image& reference_file,
                          const std::string& layer, const std::string& test_path,
                          const std::string& reference_path, ReferenceNoiseSource& source,
                          PixelMask mask) {
    const Image test = select_layers(test_file, {layer});
    const Image reference = select_layers(reference_file, {layer});
    const std::vector<std::string> layers = layer_names(reference_file);
    const bool has_stddev = std::find(layers.begin(), layers.end(), "stddev") != layers.end();
    const bool explicit_spp = source.from == "--reference-spp";
    if (explicit_spp && !has_stddev) {
        throw Error("--reference-spp: " + reference_path +
                        " has no stddev layer (the per-sample standard deviation it needs)",
                    kExitUsage);
    }
    if (explicit_spp && layer != "beauty") {
        throw Error(
            "--reference-spp: the reference's stddev layer describes the beauty layer, "
            "not --aov " +
                layer,
            kExitUsage);
    }
    if (source.spp > 0.0 && !has_stddev) {
        source.note = reference_path + " has no stddev layer";
    } else if (source.spp > 0.0 && layer != "beauty") {
        source.note = "the reference's stddev layer describes the beauty layer, not " + layer;
    } else if (source.spp > 0.0) {
        const Image stddev = stddev_matching(reference_file, reference, reference_path);
        return image_error_net(test, reference, stddev, source.spp, test_path, mask);
    }
    return image_error(test, reference, test_path, mask);
}

// The --mask image: the layer --mask-aov of FILE (default its first), its first channel.
Image read_mask(const ParsedArguments& arguments) {
    const std::string path = arguments.value("--mask");
    const Image file = read_image(path);
    const std::string layer = arguments.value("--mask-aov", layer_names(file).front());
    const std::vector<std::string> layers = layer_names(file);
    if (std::find(layers.begin(), layers.end(), layer) == layers.end()) {
        throw Error("--mask-aov: " + path + " has no layer '" + layer + "'", kExitUsage);
    }
    return select_layers(file, {layer});
}

void print_figures(const ImageError& e, const ReferenceNoiseSource& source) {
    char line[512];
    std::snprintf(line, sizeof(line), "rmse %.6g  relmse %.6g  psnr %.3f dB\n", e.rmse, e.relmse,
                  e.psnr);
    std::cout << line;
    if (e.relmse_net) {
        std::snprintf(line, sizeof(line),
                      "relMSE net of the reference's noise %.6g (reference noise %.6g subtracted: "
                      "stddev^2/spp over r^2+0.01, spp %.0f from %s)\n",
                      *e.relmse_net, *e.reference_noise, source.spp, source.from.c_str());
        std::cout << line;
    } else {
        std::cout << "relMSE net of the reference's noise: not reported, " << source.note << "\n";
    }
    for (size_t c = 0; c < e.channels.size(); ++c) {
        std::snprintf(line, sizeof(line), "mean %-12s %.6g (reference %.6g)\n",
                      e.channels[c].c_str(), e.test_means[c], e.reference_means[c]);
        std::cout << line;
    }
    std::snprintf(line, sizeof(line), "max |difference| %.6g at pixel (%d, %d) channel %s\n",
                  e.max_error, e.max_x, e.max_y,
                  e.channels.empty() ? "" : e.channels[e.max_channel].c_str());
    std::cout << line;
}

nlohmann::json json_of(const ImageError& e, const ReferenceNoiseSource& source) {
    nlohmann::json j;
    j["rmse"] = e.rmse;
    j["relmse"] = e.relmse;
    // Net of the reference's noise: null when not known.
    j["relmse_net"] = e.relmse_net ? nlohmann::json(*e.relmse_net) : nlohmann::json(nullptr);
    j["reference_noise"] =
        e.reference_noise ? nlohmann::json(*e.reference_noise) : nlohmann::json(nullptr);
    j["reference_spp"] = e.relmse_net ? nlohmann::json(source.spp) : nlohmann::json(nullptr);
    j["psnr"] = std::isfinite(e.psnr) ? nlohmann::json(e.psnr) : nlohmann::json(nullptr);
    j["channels"] = e.channels;
    j["test_means"] = e.test_means;
    j["reference_means"] = e.reference_means;
    j["max_error"] = {{"value", e.max_error},
                      {"pixel", {e.max_x, e.max_y}},
                      {"channel", e.channels.empty() ? "" : e.channels[e.max_channel]}};
    return j;
}

}  // namespace

int run_compare_command(const std::vector<std::string>& args) {
    const std::vector<OptionSpec> specs = {
        {"--aov", "", "NAME", "layer to compare (default beauty: the R, G, B channels)"},
        {"--json", "", "FILE", "also write the figures as JSON"},
        {"--error-image", "", "FILE",
         "write a false-colour image of each pixel's relMSE (.png, .exr, .hdr, .pfm)"},
        {"--mask", "", "FILE",
         "take every figure over the pixels where FILE's mask layer is positive (FILE the size of "
         "REF)"},
        {"--mask-aov", "", "NAME",
         "the layer of --mask whose first channel is the mask (default: "
         "its first layer)"},
        {"--allow-nan", "", "",
         "accept NaN or infinite pixels: the figures are over the pixels finite in both images "
         "(without it such pixels are counted and the command fails)"},
        {"--reference-spp", "", "N",
         "samples per pixel of REF, for the relMSE net of its noise (default: `spp` of "
         "REF's .stats.json or .json beside it)"},
    };
    const ParsedArguments arguments = parse_arguments("radcache compare", args, specs);
    if (arguments.has("--help")) {
        std::cout << format_help("radcache compare TEST REF [options]",
                                 "Error of TEST against REF over one layer: RMSE, relMSE "
                                 "((v-r)^2/(r^2+0.01) averaged over pixels and channels), PSNR "
                                 "(peak 1), per-channel means and the largest difference. Where "
                                 "REF has a stddev layer (per-sample standard deviation) and its "
                                 "spp is known, also relMSE net of REF's noise: relMSE minus the "
                                 "mean of (stddev^2/spp)/(r^2+0.01), which may dip below 0. The "
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
    if (arguments.has("--mask-aov") && !arguments.has("--mask")) {
        throw Error("--mask-aov needs --mask FILE", kExitUsage);
    }
    OutputBatch outputs;  // the JSON and the error image are written together, or neither
    ReferenceNoiseSource source = find_reference_spp(arguments, reference_path);
    const Image test_file = read_image(test_path);
    const Image reference_file = read_image(reference_path);
    const Image mask_image = arguments.has("--mask") ? read_mask(arguments) : Image();
    PixelMask mask{arguments.has("--mask") ? &mask_image : nullptr};
    const NonfinitePixels nonfinite = count_nonfinite_pixels(
        select_layers(test_file, {layer}), select_layers(reference_file, {layer}), mask);
    const Image finite_mask = nonfinite.any()
                                  ? finite_pixel_mask(select_layers(test_file, {layer}),
                                                      select_layers(reference_file, {layer}), mask)
                                  : Image();
    if (nonfinite.any()) {
        if (nonfinite.finite == 0) {
            throw Error(test_path + ": no pixel is finite in both images");
        }
        mask.mask = &finite_mask;
    }
    const ImageError e =
        compare_images(test_file, reference_file, layer, test_path, reference_path, source, mask);
    print_figures(e, source);
    if (mask.mask != nullptr) {
        std::cout << "over the " << e.pixels << " pixels of the mask"
                  << (nonfinite.any() ? " that are finite in both images" : "") << "\n";
    }
    if (nonfinite.any()) {
        std::cout << "nonfinite pixels (NaN or infinite): " << nonfinite.test << " in TEST, "
                  << nonfinite.reference << " in REF\n";
        if (!arguments.has("--allow-nan")) {
            throw Error(test_path + ": " + std::to_string(nonfinite.test) +
                        " NaN or infinite pixels (" + std::to_string(nonfinite.reference) + " in " +
                        reference_path + "); --allow-nan takes the figures over the finite ones");
        }
    }
    char line[256];
    if (!error_image_path.empty()) {
        write_image(error_image_path,
                    error_image(select_layers(test_file, {layer}),
                                select_layers(reference_file, {layer}), test_path));
        std::snprintf(line, sizeof(line),
                      "error image %s: log10 relMSE per pixel, %g black to %g white\n",
                      error_image_path.string().c_str(), kErrorImageLog10Min, kErrorImageLog10Max);
        std::cout << line;
    }
    if (!json_path.empty()) {
        nlohmann::json j = json_of(e, source);
        j["test"] = test_path;
        j["reference"] = reference_path;
        j["aov"] = layer;
        j["pixels"] = e.pixels;
        j["nonfinite_pixels"] = {{"test", nonfinite.test}, {"reference", nonfinite.reference}};
        if (mask.mask != nullptr) {
            j["mask"] = arguments.value("--mask");
        }
        if (!error_image_path.empty()) {
            j["error_image"] = error_image_path.string();
        }
        write_file_atomically(json_path, j.dump(2) + "\n");
    }
    outputs.commit();
    return 0;
}

}  // namespace rc
