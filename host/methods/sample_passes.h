// A render by time (--time) for methods that build a cache and then shade camera samples over it:
// the cache is built (or extended) by the first pass, and the rest of the budget goes to further
// passes of camera samples over the same cache, their images averaged.
#pragma once

#include <functional>

#include "methods/method.h"

namespace rc {

// One pass: camera samples first .. first + spp - 1 of every pixel (the sample indices a single
// render of first + spp samples would give them, so a pixel's Sobol' points keep their
// stratification across passes). Its image is the mean over those samples.
struct SamplePass {
    int first = 0;
    int spp = 1;
};

// What a render by time needs besides its passes.
struct SamplePassBudget {
    double seconds = 0.0;  // the budget (> 0)
    int max_spp = 1;       // the most samples per pixel one pass may take (its memory)
    // Seconds since the frame began (tests give a clock of their own).
    std::function<double()> clock;
};

// Renders a frame in passes until the budget is spent. The first pass takes one sample per pixel
// and builds the cache; each later pass as many samples as the time left holds at the latest
// measured cost of a sample (a pass's seconds less its FrameResult::cache_seconds, per sample),
// at most doubling the samples so far (so the second pass takes one: a cost misjudged from the
// first pass costs at most one sample per pixel) and at most max_spp. It stops when the time
// left holds not one more sample per pixel, so the frame ends within the budget but for that one
// sample, unless the first pass alone exceeds it. The image is the mean of every sample (the
// passes' images weighted by their samples); rays and dropped samples add up; the stats are the
// first pass's, with "spp" the frame's, "passes" (each later pass's stats, first_sample, spp and
// pass_seconds) and "time" (the split: budget, passes, spp, first_pass_seconds: the cache and one
// sample per pixel, later_passes_seconds: the samples added over it).
FrameResult render_sample_passes(const SamplePassBudget& budget, const FrameHooks& hooks,
                                 const std::function<FrameResult(const SamplePass&)>& pass);

// *mean = (mean_weight * mean + weight * image) / (mean_weight + weight), pixel by pixel; an empty
// *mean becomes image. Images of other sizes or channels are an internal error.
void add_weighted(Image* mean, double mean_weight, const Image& image, double weight);

}  // namespace rc
