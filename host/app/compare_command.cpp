// `radcache compare TEST REF`: an image's error against a reference (DESIGN.md §7).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/compare_frames.h"
#include "app/compare_images.h"
#include "image/image.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/output_identity.h"

namespace rc {

namespace {

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

// Error (exit status 2) when --json or --error-image is TEST, REF, --mask, REF's stats file or
// the other output.
void check_run_files(const ParsedArguments& arguments, const ReferenceNoiseSource& source,
                     const std::filesystem::path& json_path,
                     const std::filesystem::path& error_image_path) {
    RunFiles run;
    run.input("TEST image", arguments.positionals()[0]);
    run.input("REF image", arguments.positionals()[1]);
    if (arguments.has("--mask")) {
        run.input("--mask file", arguments.value("--mask"));
    }
    if (source.spp > 0.0 && source.from != "--reference-spp") {
        run.input("REF's stats file", source.from);
    }
    if (!json_path.empty()) {
        run.output("--json", json_path);
    }
    if (!error_image_path.empty()) {
        run.output("--error-image", error_image_path);
    }
    run.check();
}

// TEST against REF, one image each. The JSON and the error image are written together at the
// end, or neither.
int compare_one(const ParsedArguments& arguments) {
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
    OutputBatch outputs;
    ReferenceNoiseSource source = find_reference_spp(arguments, reference_path);
    check_run_files(arguments, source, json_path, error_image_path);
    const Image test_file = read_image(test_path);
    const Image reference_file = read_image(reference_path);
    const Image mask_image =
        arguments.has("--mask") ? read_mask(arguments.value("--mask"), arguments) : Image();
    PixelMask mask{arguments.has("--mask") ? &mask_image : nullptr};
    const Image test = select_layers(test_file, {layer});
    int factor = 1;
    const ReferenceLayer reference =
        matched_to(reference_layer(reference_file, layer, reference_path, source), test, &factor);
    Image finite_mask;
    const NonfinitePixels nonfinite =
        exclude_nonfinite_pixels(test, reference.values, test_path, mask, finite_mask);
    const ImageError e = compare_layer(test, reference, test_path, mask);
    print_figures(e, source);
    if (factor > 1) {
        std::cout << "reference box-filtered " << factor << " x " << factor
                  << " to the test's resolution\n";
    }
    if (mask.mask != nullptr) {
        std::cout << "over the " << e.pixels << " pixels of the mask"
                  << (nonfinite.any() ? " that are finite in both images" : "") << "\n";
    }
    if (nonfinite.any()) {
        std::cout << "nonfinite pixels (NaN or infinite): " << nonfinite.test << " in TEST, "
                  << nonfinite.reference << " in REF\n";
        if (!arguments.has("--allow-nan")) {
            refuse_nonfinite_pixels(nonfinite, test_path, reference_path);
        }
    }
    char line[256];
    if (!error_image_path.empty()) {
        write_image(error_image_path, error_image(test, reference.values, test_path));
        std::snprintf(line, sizeof(line),
                      "error image %s: log10 relMSE per pixel, %g black to %g white\n",
                      error_image_path.string().c_str(), kErrorImageLog10Min, kErrorImageLog10Max);
        std::cout << line;
    }
    if (!json_path.empty()) {
        nlohmann::json j = error_json(e, source);
        j["test"] = test_path;
        j["reference"] = reference_path;
        j["aov"] = layer;
        j["pixels"] = e.pixels;
        j["reference_box_filter"] = factor;
        j["nonfinite_pixels"] = {{"test", nonfinite.test}, {"reference", nonfinite.reference}};
        if (arguments.has("--mask")) {
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

std::vector<OptionSpec> compare_options() {
    std::vector<OptionSpec> specs = {
        {"--aov", "", "NAME", "layer to compare (default beauty: the R, G, B channels)"},
        {"--json", "", "FILE", "also write the figures as JSON"},
        {"--error-image", "", "FILE",
         "write a false-colour image of each pixel's relMSE (.png, .exr, .hdr, .pfm)"},
        {"--mask", "", "FILE",
         "take every figure over the pixels where FILE's mask layer is positive (FILE the size of "
         "TEST)"},
        {"--mask-aov", "", "NAME",
         "the layer of --mask whose first channel is the mask (default: "
         "its first layer)"},
        {"--allow-nan", "", "",
         "accept NaN or infinite pixels: the figures are over the pixels finite in both images "
         "(without it such pixels are counted and the command fails)"},
        OptionSpec{"--reference-spp", "", "N",
                   "samples per pixel of REF, for the relMSE net of its noise (default: `spp` of "
                   "REF's .stats.json or .json beside it)"}
            .integers(1, std::numeric_limits<long long>::max()),
        {"--frames", "", "A:B",
         "compare frames A..B of sequences: TEST and REF (and --mask, if it has one) are names "
         "with #### for the frame number, as render -o writes them; adds the temporal error of "
         "every pair of consecutive frames (flicker)"},
    };
    return specs;
}

int compare(const ParsedArguments& arguments) {
    if (arguments.positionals().size() != 2) {
        throw Error("radcache compare needs TEST and REF images (see radcache compare --help)",
                    kExitUsage);
    }
    if (arguments.has("--mask-aov") && !arguments.has("--mask")) {
        throw Error("--mask-aov needs --mask FILE", kExitUsage);
    }
    return arguments.has("--frames") ? compare_frames(arguments) : compare_one(arguments);
}

}  // namespace

CommandSpec compare_command() {
    return {.name = "compare",
            .synopsis = "compare TEST REF",
            .summary = "an image's error against a reference",
            .usage =
                "radcache compare TEST REF [options]\n       radcache compare "
                "--frames A:B TEST#### REF#### [options]",
            .description =
                "Error of TEST against REF over one layer: RMSE, relMSE "
                "((v-r)^2/(r^2+0.01) averaged over pixels and channels), PSNR "
                "(peak 1), per-channel means and the largest difference. Where "
                "REF has a stddev layer (per-sample standard deviation) and its "
                "spp is known, also relMSE net of REF's noise: relMSE minus the "
                "mean of (stddev^2/spp)/(r^2+0.01), which may dip below 0. The "
                "error image maps log10 of a pixel's relMSE from -5 (black) "
                "through blue, magenta, red and yellow to 0 (white). With "
                "--frames: those figures for every frame, and for every frame f "
                "after A the temporal error, the mean over pixels and channels "
                "of ((v_f-v_f-1)-(r_f-r_f-1))^2/(r_f^2+0.01), net of the "
                "references' noise (both frames' stddev^2/spp over "
                "r_f^2+0.01) where known; and their means over the sequence "
                "(docs/path-tracer.md, \"Flicker\"). A REF at k times TEST's "
                "resolution on both axes is box-filtered k x k to TEST's first "
                "(its stddev as the root mean square, its spp times k^2).",
            .options = compare_options(),
            .run = compare};
}

}  // namespace rc
