// Where a pixel's camera samples fall (docs/pixel-filters.md, "Pixel samplers"): the (u, v) in
// [0, 1)^2 that the pixel filter turns into an offset from the pixel's centre.
// - Independent: two words of the camera sample's own random stream (every sample independent of
//   the others; the stddev layer then states the error of the pixel's mean exactly).
// - Sobol: sample s is point s of the two-dimensional Sobol' sequence (Sobol' 1967; its first two
//   dimensions, the van der Corput sequence and the one of the Pascal matrix mod 2, form a
//   (0, 2)-sequence: every power-of-two prefix puts one point in each elementary interval,
//   Niederreiter 1992 §4.1), digitally shifted by a random pair per pixel (an XOR of its bits:
//   every point stays uniform over the pixel, so each sample is unbiased, and the prefix keeps its
//   stratification; Kollig and Keller 2002, "Efficient multidimensional sampling", §2.2). Edges and
//   the visible light's border then converge at about 1/N in the pixel's mean instead of 1/sqrt(N)
//   — at 64 samples most of the image error of a cached method on the Cornell box
//   (docs/pixel-filters.md).
// Either way the camera sample's stream has given two words, so the dimensions after it (the
// light samples, the BRDF samples, the paths) are the same under both samplers.
#pragma once

#include "common/pixel_filter.h"
#include "shared/rng.h"
#include "shared/types.h"

// The first two dimensions of the Sobol' sequence at index s, as 32-bit fractions: bit i of s
// toggles bit 31 - i of the first (its radical inverse in base 2) and the i-th direction number
// of the second, which starts at 2^31 and is shifted into itself once per bit (v ^= v >> 1).
RC_FUNC uint2 rc_sobol_2d(uint s) {
    uint first = 0u;
    uint second = 0u;
    uint direction = 0x80000000u;
    for (uint bit = 0u; s != 0u; ++bit, s >>= 1, direction ^= direction >> 1) {
        if ((s & 1u) != 0u) {
            first |= 0x80000000u >> bit;
            second ^= direction;
        }
    }
    return (uint2)(first, second);
}

// The digital shift of a pixel's Sobol' points: two words of a Philox block of their own (counter
// word 3 differs from every random stream's), a function of the seed and the pixel only.
RC_FUNC uint2 rc_pixel_sobol_shift(uint seed_lo, uint seed_hi, uint pixel) {
    uint block[4];
    rc_philox4x32_10(pixel, 0u, 0u, 0x50495853u, seed_lo, seed_hi, block);
    return (uint2)(block[0], block[1]);
}

// Camera sample s of `pixel`: *rng becomes the sample's random stream (seed, pixel, s) past the
// two words of its (u, v), and the sample's image position (pixels, (0, 0) the top-left corner)
// is returned, drawn from the camera's sampler and filter.
RC_FUNC float2 rc_camera_sample_position(const CameraParams* camera, uint seed_lo, uint seed_hi,
                                         uint pixel, uint s, RngStream* rng) {
    *rng = rc_rng_stream(seed_lo, seed_hi, pixel, s);
    uint2 words;
    words.x = rc_rng_next_uint(rng);
    words.y = rc_rng_next_uint(rng);
    if (camera->sampler == RC_SAMPLER_SOBOL) {
        words = rc_sobol_2d(s) ^ rc_pixel_sobol_shift(seed_lo, seed_hi, pixel);
    }
    return rc_filter_sample_position(camera, pixel, rc_uint_to_unit_float(words.x),
                                     rc_uint_to_unit_float(words.y));
}
