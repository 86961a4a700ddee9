// What `radcache compare` reads besides the images: the reference's sample count and stddev layer
// (for figures net of its noise) and the --mask image; and the error of one test image against
// one reference, shared by the single-image and the frame-sequence comparison.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "image/image.h"
#include "image/image_error.h"
#include "util/cli.h"

namespace rc {

// What is known of a reference's own noise: its sample count and where it came from, or why the
// net figure is not reported.
struct ReferenceNoiseSource {
    double spp = 0.0;  // 0: unknown
    std::string from;  // "--reference-spp" or the stats file
    std::string note;  // why there is no net figure, when spp is 0
};

// The reference's sample count, from --reference-spp or else from `<stem>.stats.json` (radcache
// render --stats) or `<stem>.json` (scenes/*/reference.json) beside the reference.
ReferenceNoiseSource find_reference_spp(const ParsedArguments& arguments,
                                        const std::filesystem::path& reference_path);

// One layer of a reference and, where its noise is known, the per-sample standard deviation of
// each of its values (in the layer's channel order) and its sample count.
struct ReferenceLayer {
    Image values;
    Image stddev;  // 0 x 0 when the noise is unknown
    double spp = 0.0;
    bool noise_known() const { return spp > 0.0 && stddev.width > 0; }
};

// The layer `layer` of a reference file, with its noise where `source.spp` is known and the file
// has a stddev layer describing it (the beauty layer only); otherwise source.note says why not.
// Error (exit status 2) when --reference-spp asks for a net figure that cannot be had.
ReferenceLayer reference_layer(const Image& reference_file, const std::string& layer,
                               const std::string& reference_path, ReferenceNoiseSource& source);

// A reference at k times the test's resolution on both axes (k >= 2) box-filtered to the test's:
// the values averaged over k x k pixels, the stddev as their root mean square and the sample
// count times k^2 (the filtered pixel, a mean of k^2 pixels of spp samples each, has the variance
// mean(stddev^2) / (k^2 spp)). Any other reference is returned as it is; `factor` is set to k
// (1 when nothing was done).
ReferenceLayer matched_to(const ReferenceLayer& reference, const Image& test, int* factor);

// `test` (one layer) against the reference layer, net of its noise where known.
ImageError compare_layer(const Image& test, const ReferenceLayer& reference,
                         const std::string& test_path, PixelMask mask);

// Pixels with a NaN or infinite channel in either image are counted, never folded into
// the figures. When there are any, `finite` becomes the pixels `mask` selects that are finite in
// both and `mask` points at it; Error naming `test_path` when no pixel is left.
NonfinitePixels exclude_nonfinite_pixels(const Image& test, const Image& reference,
                                         const std::string& test_path, PixelMask& mask,
                                         Image& finite);

// The error (exit status 1) for such pixels without --allow-nan: their counts in both images.
[[noreturn]] void refuse_nonfinite_pixels(const NonfinitePixels& nonfinite,
                                          const std::string& test_path,
                                          const std::string& reference_path);

// The figures of one comparison as JSON (null where a figure is unknown); `source` gives
// reference_spp.
nlohmann::json error_json(const ImageError& e, const ReferenceNoiseSource& source);

// The mask image of `path`: its layer --mask-aov (default its first), that layer's channels.
// Error (exit status 2) naming --mask-aov when the file has no such layer.
Image read_mask(const std::string& path, const ParsedArguments& arguments);

}  // namespace rc
