// What the tests of rendering by time (--time, methods/sample_passes.h) share: comparing pass
// images with one longer render, and a render by time of the Cornell box through the command
// line with its stats checked.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "image/image.h"

namespace rc::test {

// The largest pixel difference of two images over the largest magnitude in either.
double relative_difference(const Image& a, const Image& b);

// The mean of pass images weighted by their samples per pixel.
Image mean_of_passes(const std::vector<Image>& passes, const std::vector<int>& spp);

// The passes' mean (weighted by `spp`) equals `longer`, one render of their total, in every layer
// within `tolerance` (relative); each pass's beauty differs from it (new samples, not the same).
void expect_passes_make_the_longer_render(const Image& longer, const std::vector<Image>& passes,
                                          const std::vector<int>& spp, double tolerance);

// The beauty layer of the image file at `path`: every value finite, their sum positive.
void expect_finite_lit_beauty(const std::filesystem::path& path);

// `radcache render` of the Cornell box with `options` (--method, --time, size, ...) into
// scratch_dir(scratch)/out.exr with --stats. Expects exit 0, a finite lit beauty layer and the
// time split: at least one pass, the passes' samples consecutive from the first pass's one sample
// per pixel, each at most `max_spp`, adding up to the frame's spp (the frame's, the time's and
// the render's). Returns the frame's stats (an empty object when the render failed).
nlohmann::json render_cornell_by_time(const std::string& scratch,
                                      const std::vector<std::string>& options, int max_spp);

}  // namespace rc::test
