#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "util/error.h"
#include "util/file_io.h"
#include "util/stderr_capture.h"
#include "util/text.h"

namespace rc {
namespace {

enum class Format { kExr, kHdr, kPfm, kPng };

bool format_of(const std::filesystem::path& path, Format& format, std::string& plugin) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".exr") {
        format = Format::kExr;
        plugin = "openexr";
    } else if (extension == ".hdr") {
        format = Format::kHdr;
        plugin = "hdr";
    } else if (extension == ".pfm") {
        format = Format::kPfm;
        plugin = "";  // written here: OpenImageIO 2.4's pnm writer has no PFM output
    } else if (extension == ".png") {
        format = Format::kPng;
        plugin = "png";
    } else {
        return false;
    }
    return true;
}

float srgb_encode(float linear) {
    if (!(linear > 0.0f)) {
        return 0.0f;
    }
    if (linear >= 1.0f) {
        return 1.0f;
    }
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Portable float map: "PF", the size, -1 (little-endian), then RGB floats bottom row first.
void write_pfm(const std::filesystem::path& path, int width, int height,
               const std::vector<float>& rgb) {
    static_assert(std::endian::native == std::endian::little, "PFM scale -1 means little-endian");
    std::string bytes = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
    const size_t row = static_cast<size_t>(width) * 3;
    for (int y = height - 1; y >= 0; --y) {
        bytes.append(reinterpret_cast<const char*>(rgb.data() + y * row), row * sizeof(float));
    }
    write_file_atomically(path, bytes);
}

}  // namespace

void check_output_path(const std::filesystem::path& path) {
    Format format;
    std::string plugin;
    if (!format_of(path, format, plugin)) {
        throw Error(path.string() + ": unsupported output extension '" + path.extension().string() +
                        "' (use .exr, .hdr, .pfm or .png)",
                    kExitUsage);
    }
    std::filesystem::path directory = path.parent_path();
    if (directory.empty()) {
        directory = ".";
    }
    if (!std::filesystem::is_directory(directory)) {
        throw Error(
            path.string() + ": output directory '" + directory.string() + "' does not exist",
            kExitUsage);
    }
    // Create and remove a probe file: permission bits do not tell root about read-only mounts.
    const std::filesystem::path probe = temporary_sibling(path);
    {
        std::ofstream out(probe);
        if (!out) {
            throw Error(
                path.string() + ": output directory '" + directory.string() + "' is not writable",
                kExitUsage);
        }
    }
    std::error_code ignored;
    std::filesystem::remove(probe, ignored);
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (std::filesystem::is_directory(status)) {
        throw Error(path.string() + ": output path is a directory", kExitUsage);
    }
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
        throw Error(path.string() + ": output path exists and is not a regular file", kExitUsage);
    }
}

void write_image(const std::filesystem::path& path, const Image& image,
                 const ImageWriteOptions& options) {
    Format format;
    std::string plugin;
    if (!format_of(path, format, plugin)) {
        throw Error(path.string() + ": unsupported output extension '" + path.extension().string() +
                    "' (use .exr, .hdr, .pfm or .png)");
    }
    int channels = image.channels;
    if (format == Format::kHdr || format == Format::kPfm || format == Format::kPng) {
        channels = std::min(channels, 3);  // RGB only
    }
    const size_t count = static_cast<size_t>(image.width) * image.height;
    std::vector<float> data(count * channels);
    for (size_t i = 0; i < count; ++i) {
        for (int c = 0; c < channels; ++c) {
            data[i * channels + c] = image.pixels[i * image.channels + c];
        }
    }
    const OIIO::TypeDesc stored = format == Format::kPng ? OIIO::TypeDesc::UINT8
                                  : (format == Format::kExr && options.half)
                                      ? OIIO::TypeDesc::HALF
                                      : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(image.width, image.height, channels, stored);
    if (format == Format::kExr) {
        spec.attribute("compression", "zip");
        if (image.full_width > 0) {
            spec.x = image.origin_x;
            spec.y = image.origin_y;
            spec.full_x = 0;
            spec.full_y = 0;
            spec.full_width = image.full_width;
            spec.full_height = image.full_height;
        }
        for (const auto& [name, value] : image.metadata) {
            spec.attribute(name, value);
        }
    }
    spec.channelnames.assign(image.channel_names.begin(), image.channel_names.begin() + channels);
    if (format == Format::kPng) {
        const float scale = std::exp2(options.exposure);
        for (float& value : data) {
            value = srgb_encode(value * scale);
        }
        spec.attribute("oiio:ColorSpace", "sRGB");
    }
    if (format == Format::kPfm) {
        write_pfm(path, image.width, image.height, data);
        return;
    }
    replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(plugin);
        if (!out) {
            throw Error(path.string() + ": OpenImageIO has no '" + plugin + "' writer");
        }
        if (!out->open(temporary.string(), spec) ||
            !out->write_image(OIIO::TypeDesc::FLOAT, data.data()) || !out->close()) {
            std::string message = out->geterror();
            throw Error(path.string() + ": cannot write image: " + message);
        }
    });
}

namespace {

// The reader's message and the codec's stderr chatter as one short line: lines joined with "; ",
// and chatter left out when it only repeats the message (libpng's "libpng error: X" after
// OpenImageIO's "PNG read error: X").
std::string read_failure(const std::string& message, const std::string& chatter) {
    auto lines_of = [](const std::string& text) {
        std::string joined;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            if (!line.empty()) {
                joined += (joined.empty() ? "" : "; ") + line;
            }
        }
        return joined;
    };
    std::string reason = lines_of(message);
    const std::string extra = lines_of(chatter);
    const size_t colon = extra.find(": ");
    const std::string said = colon == std::string::npos ? extra : extra.substr(colon + 2);
    if (!extra.empty() && reason.find(said) == std::string::npos) {
        reason += (reason.empty() ? "" : "; ") + extra;
    }
    return excerpt(reason, 2 * kQuoteLimit);
}

// Reads the opened image's first subimage after checking its size against the limits; the
// codec's stderr chatter joins the error line.
DecodedImage read_opened(OIIO::ImageInput& in, const std::string& name, StderrCapture& capture) {
    const OIIO::ImageSpec& spec = in.spec();
    const uint64_t pixels = static_cast<uint64_t>(std::max(spec.width, 0)) *
                            static_cast<uint64_t>(std::max(spec.height, 0));
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1) {
        throw Error(name + ": not a 2-D image with pixels (" + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height) + ", " + std::to_string(spec.nchannels) +
                    " channels)");
    }
    if (pixels > kMaxImagePixels ||
        pixels * static_cast<uint64_t>(spec.nchannels) > kMaxImageValues) {
        throw Error(name + ": image of " + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height) + " pixels and " + std::to_string(spec.nchannels) +
                    " channels, more than the limit of " + std::to_string(kMaxImagePixels) +
                    " pixels and " + std::to_string(kMaxImageValues) + " values");
    }
    DecodedImage decoded;
    decoded.integer_encoded = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                              spec.format.basetype == OIIO::TypeDesc::UINT16;
    Image& image = decoded.image;
    image = Image(spec.width, spec.height, spec.nchannels);
    image.channel_names.assign(spec.channelnames.begin(), spec.channelnames.end());
    image.channel_names.resize(static_cast<size_t>(spec.nchannels));
    if (spec.x != 0 || spec.y != 0 || spec.full_width != spec.width ||
        spec.full_height != spec.height) {
        image.origin_x = spec.x;
        image.origin_y = spec.y;
        image.full_width = spec.full_width;
        image.full_height = spec.full_height;
    }
    for (const OIIO::ParamValue& attribute : spec.extra_attribs) {
        if (attribute.type() == OIIO::TypeDesc::STRING &&
            attribute.name().string().rfind("radcache:", 0) == 0) {
            image.metadata[attribute.name().string()] = attribute.get_string();
        }
    }
    const bool read =
        in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data());
    std::string message = read ? "" : in.geterror();
    in.close();
    const std::string chatter = capture.finish();
    if (!read) {
        throw Error(name + ": cannot read image: " + read_failure(message, chatter));
    }
    return decoded;
}

[[noreturn]] void throw_open_error(const std::string& name, StderrCapture& capture) {
    const std::string message = OIIO::geterror();
    const std::string chatter = capture.finish();
    throw Error(name + ": cannot read image: " + read_failure(message, chatter));
}

}  // namespace

DecodedImage decode_image(const std::string& bytes, const std::string& name) {
    OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
    StderrCapture capture;
    {
        const std::unique_ptr<OIIO::ImageInput> probe = OIIO::ImageInput::create(name);
        if (probe && !probe->supports("ioproxy")) {
            capture.finish();
            throw Error(name + ": the " + probe->format_name() +
                        " format cannot be read from memory");
        }
    }
    OIIO::ImageSpec config;
    // The proxy named in the configuration too: some readers (PNG in OpenImageIO 2.4) look for it
    // there and otherwise open `name` on disk.
    OIIO::Filesystem::IOProxy* pointer = &proxy;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &pointer);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(name, &config, &proxy);
    if (!in) {
        throw_open_error(name, capture);
    }
    return read_opened(*in, name, capture);
}

Image read_image(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string bytes = read_file(path, kMaxImageFileBytes, "image");
    {
        const std::unique_ptr<OIIO::ImageInput> probe = OIIO::ImageInput::create(name);
        if (!probe || probe->supports("ioproxy")) {
            return decode_image(bytes, name).image;
        }
    }
    // A format without in-memory reading: from the (checked) regular file itself.
    StderrCapture capture;
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(name);
    if (!in) {
        throw_open_error(name, capture);
    }
    return read_opened(*in, name, capture).image;
}

}  // namespace rc
