// A render as one part of a larger one (docs/farm.md): a window of the image's pixels (--crop), a
// range of each pixel's samples (--sample-range), their sums (--write-sums), and the attributes
// that name what the part belongs to, so that `radcache merge` adds up only parts of one render.
#pragma once

#include <map>
#include <string>

#include "image/image.h"
#include "methods/method.h"
#include "util/cli.h"

namespace rc {

// A range of each pixel's camera samples: first .. end - 1.
struct SampleRange {
    int first = 0;
    int end = 0;
};

// --crop X0:X1,Y0:Y1 (columns X0 .. X1 - 1, rows Y0 .. Y1 - 1): Error (exit status 2) naming
// --crop for another form or an empty window.
PixelWindow parse_crop(const std::string& text);

// --sample-range S0:S1 (samples S0 .. S1 - 1, 0 <= S0 < S1 <= 2^24): Error (exit status 2) naming
// --sample-range otherwise.
SampleRange parse_sample_range(const std::string& text);

// "X0:X1,Y0:Y1" and "S0:S1", as the options and the attributes write them.
std::string window_text(const PixelWindow& window);
std::string range_text(const SampleRange& range);

// What a part's image says of the render it belongs to: the attributes "radcache:scene" (a
// fingerprint of the bytes of the scene file and of every file it reads: meshes, textures,
// includes; RecordedFiles::content_digest), "radcache:method", "radcache:options" (every option
// given but those that choose the part, its output and the device), "radcache:size" (WxH of the
// whole image), "radcache:crop", "radcache:samples" and "radcache:frame".
struct PartIdentity {
    std::string scene;
    std::string method;
    std::string options;
    int width = 0;
    int height = 0;
    PixelWindow crop;  // the whole image when no --crop is given
    SampleRange samples;
};

// The identity of the render of `arguments` (its scene's files' fingerprint `scene_digest`, its
// method, the whole image's size, the window and the samples each pixel draws).
PartIdentity part_identity(const ParsedArguments& arguments, const std::string& scene_digest,
                           const std::string& method, int width, int height,
                           const PixelWindow& crop, const SampleRange& samples);

// The attributes of `identity` for frame `frame`.
std::map<std::string, std::string> part_metadata(const PartIdentity& identity, int frame);

// The pixels of `window` of `image` (every channel).
Image cut_window(const Image& image, const PixelWindow& window);

// The image a render writes for a frame: the method's image, cut to the window when the method
// rendered the whole image, its `layers` (empty: all), then with `sums` its sums layers; placed
// in the whole image and carrying the part's attributes.
Image part_image(const FrameResult& result, const std::vector<std::string>& layers, bool sums,
                 const PartIdentity& identity, int frame);

}  // namespace rc
