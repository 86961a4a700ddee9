#include "image/temporal_error.h"

#include <string>

#include "util/error.h"

namespace rc {

namespace {

std::string size_of(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height) + " (" +
           std::to_string(image.channels) + " channels)";
}

// The four frames of a pair share one size and channel count.
void check_pair(const Image& test_previous, const Image& test, const Image& reference_previous,
                const Image& reference, const std::string& test_name) {
    for (const Image* image : {&test_previous, &test, &reference_previous}) {
        if (image->width != reference.width || image->height != reference.height ||
            image->channels != reference.channels) {
            throw Error(test_name + ": a frame of " + size_of(*image) + " in a sequence of " +
                        size_of(reference) + " frames");
        }
    }
}

// The mean over the selected values of term(v0, v1, r0, r1, x, y, c), and the pixel count.
template <typename Term>
double mean_over_mask(const Image& reference, PixelMask mask, const std::string& test_name,
                      size_t* pixels, Term term) {
    double sum = 0.0;
    size_t selected = 0;
    mask.for_each_selected(reference.width, reference.height, [&](int x, int y) {
        ++selected;
        for (int c = 0; c < reference.channels; ++c) {
            sum += term(x, y, c);
        }
    });
    check_selected_any(mask, selected, test_name);
    *pixels = selected;
    const double values = static_cast<double>(selected) * reference.channels;
    return values > 0.0 ? sum / values : 0.0;
}

}  // namespace

TemporalError temporal_error(const Image& test_previous, const Image& test,
                             const Image& reference_previous, const Image& reference,
                             const std::string& test_name, PixelMask mask) {
    check_pair(test_previous, test, reference_previous, reference, test_name);
    check_mask(mask, reference, test_name);
    TemporalError e;
    // ((v1 - v0) - (r1 - r0))^2 / (r1^2 + 0.01): relMSE's term for the change between frames.
    e.temporal_error =
        mean_over_mask(reference, mask, test_name, &e.pixels, [&](int x, int y, int c) {
            const double change = static_cast<double>(test.at(x, y, c)) - test_previous.at(x, y, c);
            const double reference_change =
                static_cast<double>(reference.at(x, y, c)) - reference_previous.at(x, y, c);
            const double r = reference.at(x, y, c);
            const double d = change - reference_change;
            return d * d / (r * r + 0.01);
        });
    return e;
}

TemporalError temporal_error_net(const Image& test_previous, const Image& test,
                                 const Image& reference_previous, const Image& reference,
                                 ReferenceNoise noise_previous, ReferenceNoise noise,
                                 const std::string& test_name, PixelMask mask) {
    TemporalError e =
        temporal_error(test_previous, test, reference_previous, reference, test_name, mask);
    for (const ReferenceNoise& n : {noise_previous, noise}) {
        if (n.stddev == nullptr) {
            throw Error(test_name + ": no stddev image for the reference's noise");
        }
        check_comparable(*n.stddev, reference, "the reference's stddev layer");
        if (!(n.spp > 0.0)) {
            throw Error(
                "the reference's sample count must be positive, got " + std::to_string(n.spp),
                kExitUsage);
        }
    }
    // Var(r1 - r0) = s0^2 / spp0 + s1^2 / spp1 for independent frames, over r1^2 + 0.01.
    size_t pixels = 0;
    e.reference_noise =
        mean_over_mask(reference, mask, test_name, &pixels, [&](int x, int y, int c) {
            const double s0 = noise_previous.stddev->at(x, y, c);
            const double s1 = noise.stddev->at(x, y, c);
            const double r = reference.at(x, y, c);
            return (s0 * s0 / noise_previous.spp + s1 * s1 / noise.spp) / (r * r + 0.01);
        });
    e.temporal_error_net = e.temporal_error - *e.reference_noise;
    return e;
}

}  // namespace rc
