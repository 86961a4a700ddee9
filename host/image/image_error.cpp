#include "image/image_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.h"

namespace rc {

double relative_squared_error(double value, double reference) {
    const double d = value - reference;
    return d * d / (reference * reference + 0.01);
}

void check_comparable(const Image& test, const Image& reference, const std::string& test_name) {
    if (test.width != reference.width || test.height != reference.height) {
        throw Error(test_name + ": " + std::to_string(test.width) + "x" +
                    std::to_string(test.height) + " against a " + std::to_string(reference.width) +
                    "x" + std::to_string(reference.height) + " reference");
    }
    if (test.channels != reference.channels) {
        throw Error(test_name + ": " + std::to_string(test.channels) + " channels against " +
                    std::to_string(reference.channels) + " in the reference");
    }
}

void check_mask(const PixelMask& mask, const Image& reference, const std::string& test_name) {
    if (mask.mask != nullptr &&
        (mask.mask->width != reference.width || mask.mask->height != reference.height ||
         mask.mask->channels < 1)) {
        throw Error(test_name + ": a " + std::to_string(mask.mask->width) + "x" +
                        std::to_string(mask.mask->height) + " mask against a " +
                        std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                        " reference",
                    kExitUsage);
    }
}

void check_selected_any(const PixelMask& mask, size_t selected, const std::string& test_name) {
    if (mask.mask != nullptr && selected == 0) {
        throw Error(test_name + ": the mask selects no pixel", kExitUsage);
    }
}

namespace {

// sRGB transfer function, display value to linear.
float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

namespace {

bool pixel_finite(const Image& image, int x, int y) {
    for (int c = 0; c < image.channels; ++c) {
        if (!std::isfinite(image.at(x, y, c))) {
            return false;
        }
    }
    return true;
}

}  // namespace

NonfinitePixels count_nonfinite_pixels(const Image& test, const Image& reference, PixelMask mask) {
    check_comparable(test, reference, "image");
    check_mask(mask, reference, "image");
    NonfinitePixels counts;
    mask.for_each_selected(test.width, test.height, [&](int x, int y) {
        const bool test_finite = pixel_finite(test, x, y);
        const bool reference_finite = pixel_finite(reference, x, y);
        counts.test += test_finite ? 0 : 1;
        counts.reference += reference_finite ? 0 : 1;
        counts.finite += test_finite && reference_finite ? 1 : 0;
    });
    return counts;
}

Image finite_pixel_mask(const Image& test, const Image& reference, PixelMask mask) {
    Image finite(reference.width, reference.height, 1);
    finite.channel_names = {"Y"};
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            finite.at(x, y, 0) =
                mask.selects(x, y) && pixel_finite(test, x, y) && pixel_finite(reference, x, y)
                    ? 1.0f
                    : 0.0f;
        }
    }
    return finite;
}

ImageError image_error(const Image& test, const Image& reference, const std::string& test_name,
                       PixelMask mask) {
    check_comparable(test, reference, test_name);
    check_mask(mask, reference, test_name);
    ImageError e;
    const int channels = test.channels;
    e.channels = test.channel_names;
    e.test_means.assign(channels, 0.0);
    e.reference_means.assign(channels, 0.0);
    double squared = 0.0;
    double relative = 0.0;
    mask.for_each_selected(test.width, test.height, [&](int x, int y) {
        ++e.pixels;
        for (int c = 0; c < channels; ++c) {
            const double v = test.at(x, y, c);
            const double r = reference.at(x, y, c);
            const double d = v - r;
            squared += d * d;
            relative += relative_squared_error(v, r);
            e.test_means[c] += v;
            e.reference_means[c] += r;
            if (!(std::fabs(d) <= e.max_error)) {  // NaN counts as the largest error
                e.max_error =
                    std::isnan(d) ? std::numeric_limits<double>::infinity() : std::fabs(d);
                e.max_x = x;
                e.max_y = y;
                e.max_channel = c;
            }
        }
    });
    check_selected_any(mask, e.pixels, test_name);
    const double values = static_cast<double>(e.pixels) * channels;
    if (values > 0.0) {
        e.rmse = std::sqrt(squared / values);
        e.relmse = relative / values;
        const double pixels = static_cast<double>(e.pixels);
        for (int c = 0; c < channels; ++c) {
            e.test_means[c] /= pixels;
            e.reference_means[c] /= pixels;
        }
    }
    const double mse = e.rmse * e.rmse;
    e.psnr = mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity();
    return e;
}

double reference_noise_relmse(const Image& reference, const Image& stddev, double spp,
                              PixelMask mask) {
    check_comparable(stddev, reference, "the reference's stddev layer");
    check_mask(mask, reference, "the reference's stddev layer");
    if (!(spp > 0.0)) {
        throw Error("the reference's sample count must be positive, got " + std::to_string(spp),
                    kExitUsage);
    }
    // Var(r) = stddev^2 / spp per value, over the relMSE denominator r^2 + 0.01, averaged.
    double noise = 0.0;
    size_t values = 0;
    mask.for_each_selected(reference.width, reference.height, [&](int x, int y) {
        for (int c = 0; c < reference.channels; ++c) {
            const double r = reference.at(x, y, c);
            const double s = stddev.at(x, y, c);
            noise += s * s / spp / (r * r + 0.01);
            ++values;
        }
    });
    return values == 0 ? 0.0 : noise / static_cast<double>(values);
}

ImageError image_error_net(const Image& test, const Image& reference, const Image& reference_stddev,
                           double reference_spp, const std::string& test_name, PixelMask mask) {
    ImageError e = image_error(test, reference, test_name, mask);
    // relMSE_net = relMSE - mean(Var(r) / (r^2 + 0.01)); kept signed.
    e.reference_noise = reference_noise_relmse(reference, reference_stddev, reference_spp, mask);
    e.relmse_net = e.relmse - *e.reference_noise;
    return e;
}

void error_scale_colour(double t, float srgb[3]) {
    // Control points of the scale in display space, evenly spaced in t: black, blue, magenta,
    // red, yellow, white. Lightness rises monotonically so the scale also reads in grey.
    static constexpr float kStops[6][3] = {{0.0f, 0.0f, 0.0f},  {0.1f, 0.1f, 0.6f},
                                           {0.6f, 0.1f, 0.6f},  {0.9f, 0.2f, 0.1f},
                                           {1.0f, 0.85f, 0.1f}, {1.0f, 1.0f, 1.0f}};
    const double clamped = std::isnan(t) ? 1.0 : std::min(1.0, std::max(0.0, t));
    const double position = clamped * 5.0;
    const int stop = std::min(4, static_cast<int>(position));
    const float f = static_cast<float>(position - stop);
    for (int c = 0; c < 3; ++c) {
        srgb[c] = kStops[stop][c] + f * (kStops[stop + 1][c] - kStops[stop][c]);
    }
}

Image error_image(const Image& test, const Image& reference, const std::string& test_name) {
    check_comparable(test, reference, test_name);
    Image image(test.width, test.height, 3);
    image.channel_names = {"R", "G", "B"};
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            double relative = 0.0;
            for (int c = 0; c < test.channels; ++c) {
                relative += relative_squared_error(test.at(x, y, c), reference.at(x, y, c));
            }
            relative /= std::max(1, test.channels);
            // NaN maps to the top of the scale; zero error to the bottom.
            const double log_error = relative > 0.0         ? std::log10(relative)
                                     : std::isnan(relative) ? kErrorImageLog10Max
                                                            : kErrorImageLog10Min;
            float srgb[3];
            error_scale_colour(
                (log_error - kErrorImageLog10Min) / (kErrorImageLog10Max - kErrorImageLog10Min),
                srgb);
            for (int c = 0; c < 3; ++c) {
                image.at(x, y, c) = srgb_to_linear(srgb[c]);
            }
        }
    }
    return image;
}

}  // namespace rc
