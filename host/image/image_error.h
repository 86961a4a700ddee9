// Error of an image against a reference (DESIGN.md §7): RMSE, relative MSE, PSNR, per-channel
// means and the largest absolute difference.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace rc {

struct ImageError {
    double rmse = 0.0;    // sqrt of the mean of (v - r)^2 over pixels and channels
    double relmse = 0.0;  // mean of (v - r)^2 / (r^2 + 0.01) over pixels and channels
    double psnr = 0.0;    // 10 log10(1 / MSE): peak value 1 (infinite for identical images)
    std::vector<std::string> channels;
    std::vector<double> test_means;  // per channel
    std::vector<double> reference_means;
    double max_error = 0.0;  // largest |v - r| and where it is
    int max_x = 0;
    int max_y = 0;
    int max_channel = 0;
};

// The relMSE term of one value: (v - r)^2 / (r^2 + 0.01).
double relative_squared_error(double value, double reference);

// `test` against `reference`; Error naming `test_name` when their sizes or channel counts differ.
ImageError image_error(const Image& test, const Image& reference,
                       const std::string& test_name = "image");

// The false-colour scale of error images: log10 of a pixel's relMSE from kErrorImageLog10Min
// (black) to kErrorImageLog10Max (white), through blue, magenta, red and yellow.
constexpr double kErrorImageLog10Min = -5.0;
constexpr double kErrorImageLog10Max = 0.0;

// The display colour (sRGB-encoded, 0..1) of a position t in [0, 1] on the error scale.
void error_scale_colour(double t, float srgb[3]);

// A false-colour RGB image of the per-pixel relMSE (the mean over channels of
// relative_squared_error) of `test` against `reference`, in linear values whose sRGB encoding
// is error_scale_colour. Same checks as image_error.
Image error_image(const Image& test, const Image& reference,
                  const std::string& test_name = "image");

}  // namespace rc
