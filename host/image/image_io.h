// Image files through OpenImageIO: .exr (float or half; every channel, AOVs as layers named
// "layer.R"), .hdr and .pfm (the first three channels, float), and .png (the first three
// channels, exposure, clamped, sRGB-encoded 8 bits). Files are written to a temporary name and
// renamed, so a failed write leaves nothing behind.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "image/image.h"

namespace rc {

struct ImageWriteOptions {
    float exposure = 0.0f;  // stops applied before an 8-bit encoding
    bool half = false;      // .exr: 16-bit half floats instead of 32-bit floats
};

// Throws Error (exit status 2) unless the extension is a supported output format and the
// directory exists and is writable: checked before rendering starts.
void check_output_path(const std::filesystem::path& path);

void write_image(const std::filesystem::path& path, const Image& image,
                 const ImageWriteOptions& options = {});

// The largest image read: pixels, and values (pixels times channels); a file is also at most
// kMaxImageFileBytes long. A header claiming more is refused before any pixel is allocated (the
// issue's 74-byte PNG that claims 60000x60000 pixels).
inline constexpr uint64_t kMaxImagePixels = uint64_t{1} << 27;
inline constexpr uint64_t kMaxImageValues = uint64_t{1} << 29;
inline constexpr uint64_t kMaxImageFileBytes = uint64_t{1} << 30;

// Reads any image OpenImageIO can read, as float: a regular file only, within the limits above.
// What the codec prints on stderr (libpng's own lines) goes into the error line instead.
Image read_image(const std::filesystem::path& path);

// An image decoded from a file's bytes (`name` picks the format by its extension and names the
// file in errors), with the limits and error lines of read_image.
struct DecodedImage {
    Image image;
    bool integer_encoded = false;  // stored as 8- or 16-bit integers (display-encoded)
};
DecodedImage decode_image(const std::string& bytes, const std::string& name);

}  // namespace rc
