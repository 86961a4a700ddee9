#include "app/render_parts.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <regex>
#include <set>

#include "app/recorded_files.h"
#include "util/error.h"
#include "util/file_io.h"
#include "util/text.h"

namespace rc {
namespace {

// A non-negative integer of `text` at most `most`, or -1.
long long bounded(const std::string& text, long long most) {
    errno = 0;
    const long long number = std::strtoll(text.c_str(), nullptr, 10);
    return errno != 0 || number > most ? -1 : number;
}

// The options that choose a part, its outputs or the device: not part of what it renders.
const std::set<std::string>& part_options() {
    static const std::set<std::string> names = {
        "--output",     "--crop",      "--sample-range",  "--spp",          "--write-sums",
        "--stats",      "--quiet",     "--frames",        "--half",         "--aovs",
        "--strict",     "--device",    "--kernel-dir",    "--dump-kernels", "--no-kernel-cache",
        "--local-size", "--max-chunk", "--device-memory", "--bvh",          "--write-from"};
    return names;
}

// A farmhash fingerprint of the bytes of the file at `path` (16 hex digits), or "unreadable"
// (the run's own read of it then names the problem).
std::string file_fingerprint(const std::string& path) {
    std::string bytes;
    try {
        bytes = read_file(path, std::numeric_limits<uint64_t>::max(), "--cache-in file");
    } catch (const Error&) {
        return "unreadable";
    }
    return bytes_digest(bytes);
}

}  // namespace

PixelWindow parse_crop(const std::string& text) {
    static const std::regex form(R"(^(\d{1,6}):(\d{1,6}),(\d{1,6}):(\d{1,6})$)");
    std::smatch match;
    if (text.size() > 64 || !std::regex_match(text, match, form)) {
        throw Error("--crop: expected X0:X1,Y0:Y1, got '" + excerpt(text) + "'", kExitUsage);
    }
    PixelWindow window;
    window.x0 = static_cast<int>(bounded(match[1].str(), 1 << 16));
    window.x1 = static_cast<int>(bounded(match[2].str(), 1 << 16));
    window.y0 = static_cast<int>(bounded(match[3].str(), 1 << 16));
    window.y1 = static_cast<int>(bounded(match[4].str(), 1 << 16));
    if (window.x0 < 0 || window.x1 < 0 || window.y0 < 0 || window.y1 < 0) {
        throw Error("--crop " + text + ": a bound beyond 65536", kExitUsage);
    }
    if (window.empty()) {
        throw Error("--crop " + text + ": an empty window (X1 must exceed X0, Y1 Y0)", kExitUsage);
    }
    return window;
}

SampleRange parse_sample_range(const std::string& text) {
    static const std::regex form(R"(^(\d{1,9}):(\d{1,9})$)");
    std::smatch match;
    if (text.size() > 64 || !std::regex_match(text, match, form)) {
        throw Error("--sample-range: expected S0:S1, got '" + excerpt(text) + "'", kExitUsage);
    }
    const long long first = bounded(match[1].str(), 1 << 24);
    const long long end = bounded(match[2].str(), 1 << 24);
    if (first < 0 || end < 0) {
        throw Error("--sample-range " + text + ": a bound beyond 16777216", kExitUsage);
    }
    if (end <= first) {
        throw Error("--sample-range " + text + ": an empty range (S1 must exceed S0)", kExitUsage);
    }
    return {static_cast<int>(first), static_cast<int>(end)};
}

std::string window_text(const PixelWindow& window) {
    return std::to_string(window.x0) + ":" + std::to_string(window.x1) + "," +
           std::to_string(window.y0) + ":" + std::to_string(window.y1);
}

std::string range_text(const SampleRange& range) {
    return std::to_string(range.first) + ":" + std::to_string(range.end);
}

PartIdentity part_identity(const ParsedArguments& arguments, const std::string& scene_digest,
                           const std::string& method, int width, int height,
                           const PixelWindow& crop, const SampleRange& samples) {
    PartIdentity identity;
    identity.scene = scene_digest;
    identity.method = method;
    for (const std::string& name : arguments.names()) {
        if (part_options().count(name) != 0) {
            continue;
        }
        identity.options += (identity.options.empty() ? "" : " ") + name;
        for (const std::string& value : arguments.values(name)) {
            identity.options += " " + value;
            if (name == "--cache-in") {  // what the part read, not only where from
                identity.options += " (content " + file_fingerprint(value) + ")";
            }
        }
    }
    identity.width = width;
    identity.height = height;
    identity.crop = crop.empty() ? PixelWindow{0, width, 0, height} : crop;
    identity.samples = samples;
    return identity;
}

std::map<std::string, std::string> part_metadata(const PartIdentity& identity, int frame) {
    return {
        {"radcache:scene", identity.scene},
        {"radcache:method", identity.method},
        {"radcache:options", identity.options},
        {"radcache:size", std::to_string(identity.width) + "x" + std::to_string(identity.height)},
        {"radcache:crop", window_text(identity.crop)},
        {"radcache:samples", range_text(identity.samples)},
        {"radcache:frame", std::to_string(frame)}};
}

Image cut_window(const Image& image, const PixelWindow& window) {
    Image cut(window.width(), window.height(), image.channels);
    cut.channel_names = image.channel_names;
    const size_t row = static_cast<size_t>(window.width()) * image.channels;
    for (int y = window.y0; y < window.y1; ++y) {
        const float* from =
            &image.pixels[(static_cast<size_t>(y) * image.width + window.x0) * image.channels];
        std::copy(from, from + row,
                  cut.pixels.begin() + static_cast<ptrdiff_t>((y - window.y0) * row));
    }
    return cut;
}

namespace {

// `image` with the channels of `extra` after its own.
Image with_channels(const Image& image, const Image& extra) {
    Image joined(image.width, image.height, image.channels + extra.channels);
    joined.channel_names = image.channel_names;
    joined.channel_names.insert(joined.channel_names.end(), extra.channel_names.begin(),
                                extra.channel_names.end());
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    for (size_t p = 0; p < pixels; ++p) {
        float* out = &joined.pixels[p * joined.channels];
        std::copy_n(&image.pixels[p * image.channels], image.channels, out);
        std::copy_n(&extra.pixels[p * extra.channels], extra.channels, out + image.channels);
    }
    return joined;
}

}  // namespace

Image part_image(const FrameResult& result, const std::vector<std::string>& layers, bool sums,
                 const PartIdentity& identity, int frame) {
    const PixelWindow& crop = identity.crop;
    const auto in_window = [&](const Image& image) {
        const bool whole = image.width == identity.width && image.height == identity.height;
        return whole && (crop.width() != image.width || crop.height() != image.height)
                   ? cut_window(image, crop)
                   : image;
    };
    Image image = in_window(result.image);
    if (!layers.empty()) {
        image = select_layers(image, layers);
    }
    if (sums) {
        image = with_channels(image, in_window(result.sums));
    }
    image.origin_x = crop.x0;
    image.origin_y = crop.y0;
    image.full_width = identity.width;
    image.full_height = identity.height;
    image.metadata = part_metadata(identity, frame);
    return image;
}

}  // namespace rc
