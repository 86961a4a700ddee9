// `radcache compare --frames A:B TEST REF`: the error of every frame of a sequence against its
// reference and the temporal error (flicker) of every pair of consecutive frames
// (docs/path-tracer.md, "Flicker").
#pragma once

#include "util/cli.h"

namespace rc {

// Compares frames A..B of the sequences named by the positionals TEST and REF (#### the frame
// number), with compare's --aov, --mask (a name with #### for one mask per frame), --mask-aov,
// --reference-spp and --json; returns the exit status. Error (exit status 2) for a bad range,
// names without ####, or --error-image; (exit status 1) for a missing frame or frames of other
// sizes.
int compare_frames(const ParsedArguments& arguments);

}  // namespace rc
