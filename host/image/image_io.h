// Image files through OpenImageIO: .exr (float or half; every channel, AOVs as layers named
// "layer.R"), .hdr and .pfm (the first three channels, float), and .png (the first three
// channels, exposure, clamped, sRGB-encoded 8 bits). Files are written to a temporary name and
// renamed, so a failed write leaves nothing behind.
#pragma once

#include <filesystem>

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

// Reads any image OpenImageIO can read, as float.
Image read_image(const std::filesystem::path& path);

}  // namespace rc
