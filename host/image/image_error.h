// Error of an image against a reference (DESIGN.md §7): RMSE, relative MSE, PSNR, per-channel
// means and the largest absolute difference.
#pragma once

#include <cstddef>
#include <optional>
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
    // Net of the reference's own noise (image_error_net; absent when the reference's noise is
    // unknown). reference_noise is the mean over pixels and channels of
    // (stddev^2 / spp_ref) / (r^2 + 0.01), the reference's expected share of relmse, and
    // relmse_net = relmse - reference_noise. relmse_net estimates the test image's own error; for
    // a test image as good as the reference it scatters around 0 and may be slightly negative
    // (the sign is kept so that averages over runs stay unbiased).
    std::optional<double> reference_noise;
    std::optional<double> relmse_net;
    size_t pixels = 0;  // the pixels the figures are over (the mask's, or every pixel)
};

// The pixels an error is taken over: those whose value in `mask`'s first channel is positive
// (NaN is not), or every pixel when `mask` is null. Error naming `test_name` when the mask's size
// differs from the images'.
struct PixelMask {
    const Image* mask = nullptr;
    bool selects(int x, int y) const { return mask == nullptr || mask->at(x, y, 0) > 0.0f; }

    // Calls visit(x, y) for every pixel of a width x height image it selects, row by row.
    template <class Visit>
    void for_each_selected(int width, int height, Visit visit) const {
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                if (selects(x, y)) {
                    visit(x, y);
                }
            }
        }
    }
};

// Pixels with a NaN or infinite channel (compare counts them instead of reporting
// "psnr inf"), among those a mask selects.
struct NonfinitePixels {
    size_t test = 0;       // pixels of the test image with a NaN or infinite channel
    size_t reference = 0;  // the same in the reference
    size_t finite = 0;     // pixels finite in both
    bool any() const { return test > 0 || reference > 0; }
};
NonfinitePixels count_nonfinite_pixels(const Image& test, const Image& reference,
                                       PixelMask mask = {});

// A one-channel mask of the pixels `mask` selects that are finite in both images (1, else 0).
Image finite_pixel_mask(const Image& test, const Image& reference, PixelMask mask = {});

// Error naming `test_name` when `test` and `reference` differ in size or channel count.
void check_comparable(const Image& test, const Image& reference, const std::string& test_name);

// Error (exit status 2) naming `test_name` when `mask` is set and its size differs from
// `reference`'s.
void check_mask(const PixelMask& mask, const Image& reference, const std::string& test_name);

// Error (exit status 2) naming `test_name` when `mask` is set and selected none of the pixels
// (`selected` of them).
void check_selected_any(const PixelMask& mask, size_t selected, const std::string& test_name);

// The relMSE term of one value: (v - r)^2 / (r^2 + 0.01).
double relative_squared_error(double value, double reference);

// `test` against `reference` over the pixels `mask` selects (means and the largest difference
// too); Error naming `test_name` when their sizes or channel counts differ, or when the mask
// selects no pixel.
ImageError image_error(const Image& test, const Image& reference,
                       const std::string& test_name = "image", PixelMask mask = {});

// The expected relMSE contribution of the reference's own noise: the mean over pixels and channels
// of Var(r) / (r^2 + 0.01), Var(r) = stddev^2 / spp, where `stddev` holds the standard deviation of
// one sample of each reference value (the same size and channel count as `reference`) and `spp` is
// the reference's sample count, over the pixels `mask` selects. Error when the sizes differ or spp
// is not positive.
double reference_noise_relmse(const Image& reference, const Image& stddev, double spp,
                              PixelMask mask = {});

// image_error with reference_noise and relmse_net filled in from the reference's per-sample
// standard deviation `reference_stddev` and its sample count `reference_spp`. Since
// E[(v - r)^2] = (v - mu)^2 + Var(r) for a reference r independent of v with mean mu, the net
// figure is the error against the reference's mean to first order (the denominator uses r, not mu).
ImageError image_error_net(const Image& test, const Image& reference, const Image& reference_stddev,
                           double reference_spp, const std::string& test_name = "image",
                           PixelMask mask = {});

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
