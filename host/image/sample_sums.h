// A path-traced film as per-pixel sums (--write-sums): the sums of each layer's samples, the sums
// of the beauty samples' squares and the count of samples per pixel, so that renders of parts of
// a pixel's samples add up to the render of all of them (`radcache merge`).
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "shared/compat.h"

namespace rc {

// The sums layers, in channel order: beauty_sum, beauty_sumsq, direct_sum, indirect_sum,
// albedo_sum, normal_sum (R, G, B each), then count (count.Y: the pixel's finite samples).
extern const char* const kSumsLayers[7];

// The sums image of a path tracer's film (kernels/shared/film.h: RC_PT_FILM_SLOTS float4 a pixel,
// the beauty slot's w counting the samples).
Image film_sums(const std::vector<shared::float4>& film, int width, int height);

// Whether `image` holds every sums layer.
bool has_sums(const Image& image);

// The sums layers of `image` alone, in kSumsLayers' order (Error when one is missing).
Image sums_of(const Image& image);

// The path tracer's image of `sums`: beauty, direct, indirect, albedo and normal (the means over
// the pixel's samples) and stddev (the standard deviation of one beauty sample, unbiased), the
// float arithmetic of the path tracer's own, so the same sums give bitwise the same image.
Image resolve_sums(const Image& sums);

}  // namespace rc
