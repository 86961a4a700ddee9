// Flicker of an image sequence against reference frames (docs/path-tracer.md, "Flicker"): the
// temporal error of a pair of consecutive frames, the change between them against the same
// change in the references, with relMSE's denominator.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "image/image.h"
#include "image/image_error.h"

namespace rc {

struct TemporalError {
    // The mean over pixels and channels of ((v1 - v0) - (r1 - r0))^2 / (r1^2 + 0.01), for test
    // frames v0, v1 and reference frames r0, r1 (frames f - 1 and f).
    double temporal_error = 0.0;
    // Net of the references' own noise (temporal_error_net; absent when unknown):
    // reference_noise is the mean of (s0^2 / spp0 + s1^2 / spp1) / (r1^2 + 0.01), the expected
    // share of two independent reference frames' noise in temporal_error, and
    // temporal_error_net = temporal_error - reference_noise, kept signed.
    std::optional<double> reference_noise;
    std::optional<double> temporal_error_net;
    size_t pixels = 0;  // the pixels the figure is over (the mask's, or every pixel)
};

// The temporal error of test frames `test_previous`, `test` against reference frames
// `reference_previous`, `reference` over the pixels `mask` selects; Error naming `test_name`
// when the four images' sizes or channel counts differ, or when the mask selects no pixel.
TemporalError temporal_error(const Image& test_previous, const Image& test,
                             const Image& reference_previous, const Image& reference,
                             const std::string& test_name = "image", PixelMask mask = {});

// A reference frame's per-sample standard deviation (the size and channels of the frame) and its
// sample count.
struct ReferenceNoise {
    const Image* stddev = nullptr;
    double spp = 0.0;
};

// temporal_error with reference_noise and temporal_error_net filled in from both reference
// frames' noise. E[(d - dr)^2] = (d - E dr)^2 + Var(r0) + Var(r1) for references independent of
// the test and of each other, d = v1 - v0 and dr = r1 - r0; where the reference frames share
// random numbers (a radcache run draws the same samples in every frame) their noise is
// positively correlated and the subtracted share an upper bound. Error when a stddev image's
// size differs or an spp is not positive.
TemporalError temporal_error_net(const Image& test_previous, const Image& test,
                                 const Image& reference_previous, const Image& reference,
                                 ReferenceNoise noise_previous, ReferenceNoise noise,
                                 const std::string& test_name = "image", PixelMask mask = {});

}  // namespace rc
