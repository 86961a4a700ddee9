// An image's error against its reference (image_error) in the words the accuracy tests print.
#pragma once

#include <string>

#include "image/image_error.h"

namespace rc::test {

// "relMSE R, means A B C (reference D E F)": relMSE by %.3g, the first three channels' means by
// %.4f.
std::string error_summary(const ImageError& e);

}  // namespace rc::test
