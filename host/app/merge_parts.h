// `radcache merge`: the parts of one render (docs/farm.md) — windows of its image (--crop) and
// ranges of its pixels' samples (--sample-range, with --write-sums) — assembled into one image.
#pragma once

#include <filesystem>
#include <vector>

#include "image/image.h"

namespace rc {

// The image of `parts` (.exr files written by radcache render): the windows side by side in the
// smallest window holding them all, and within a window the sums of its parts' samples resolved
// as one render of all of them would resolve them (image/sample_sums.h). Error (exit status 1)
// naming the part when one is not a radcache part, belongs to another render (scene, method,
// options, image size, frame, layers), overlaps another (pixels or samples), leaves a gap (pixels
// or samples), or has no sums where sample ranges are added.
Image merge_parts(const std::vector<std::filesystem::path>& parts);

}  // namespace rc
