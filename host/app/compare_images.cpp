#include "app/compare_images.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "image/image_io.h"
#include "util/error.h"

namespace rc {

namespace {

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

}  // namespace

ReferenceNoiseSource find_reference_spp(const ParsedArguments& arguments,
                                        const std::filesystem::path& reference_path) {
    ReferenceNoiseSource source;
    if (arguments.has("--reference-spp")) {
        source.spp = static_cast<double>(arguments.integer("--reference-spp", 0));
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

ReferenceLayer reference_layer(const Image& reference_file, const std::string& layer,
                               const std::string& reference_path, ReferenceNoiseSource& source) {
    ReferenceLayer reference;
    reference.values = select_layers(reference_file, {layer});
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
        reference.stddev = stddev_matching(reference_file, reference.values, reference_path);
        reference.spp = source.spp;
    }
    return reference;
}

ReferenceLayer matched_to(const ReferenceLayer& reference, const Image& test, int* factor) {
    *factor = 1;
    const int w = reference.values.width;
    const int h = reference.values.height;
    if (test.width <= 0 || test.height <= 0 || w % test.width != 0 || h % test.height != 0 ||
        w / test.width != h / test.height || w / test.width < 2) {
        return reference;
    }
    const int k = w / test.width;
    ReferenceLayer filtered;
    filtered.values = box_filtered(reference.values, k);
    if (reference.noise_known()) {
        Image variance = reference.stddev;
        for (float& v : variance.pixels) {
            v *= v;
        }
        filtered.stddev = box_filtered(variance, k);
        for (float& v : filtered.stddev.pixels) {
            v = std::sqrt(v);
        }
        filtered.spp = reference.spp * k * k;
    }
    *factor = k;
    return filtered;
}

ImageError compare_layer(const Image& test, const ReferenceLayer& reference,
                         const std::string& test_path, PixelMask mask) {
    if (reference.noise_known()) {
        return image_error_net(test, reference.values, reference.stddev, reference.spp, test_path,
                               mask);
    }
    return image_error(test, reference.values, test_path, mask);
}

NonfinitePixels exclude_nonfinite_pixels(const Image& test, const Image& reference,
                                         const std::string& test_path, PixelMask& mask,
                                         Image& finite) {
    check_comparable(test, reference, test_path);
    check_mask(mask, reference, test_path);
    const NonfinitePixels nonfinite = count_nonfinite_pixels(test, reference, mask);
    if (!nonfinite.any()) {
        return nonfinite;
    }
    if (nonfinite.finite == 0) {
        throw Error(test_path + ": no pixel is finite in both images");
    }
    finite = finite_pixel_mask(test, reference, mask);
    mask.mask = &finite;
    return nonfinite;
}

void refuse_nonfinite_pixels(const NonfinitePixels& nonfinite, const std::string& test_path,
                             const std::string& reference_path) {
    throw Error(test_path + ": " + std::to_string(nonfinite.test) + " NaN or infinite pixels (" +
                std::to_string(nonfinite.reference) + " in " + reference_path +
                "); --allow-nan takes the figures over the finite ones");
}

nlohmann::json error_json(const ImageError& e, const ReferenceNoiseSource& source) {
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

Image read_mask(const std::string& path, const ParsedArguments& arguments) {
    const Image file = read_image(path);
    const std::vector<std::string> layers = layer_names(file);
    const std::string layer = arguments.value("--mask-aov", layers.front());
    if (std::find(layers.begin(), layers.end(), layer) == layers.end()) {
        throw Error("--mask-aov: " + path + " has no layer '" + layer + "'", kExitUsage);
    }
    return select_layers(file, {layer});
}

}  // namespace rc
