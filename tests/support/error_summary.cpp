#include "error_summary.h"

#include <cstdio>

namespace rc::test {

std::string error_summary(const ImageError& e) {
    char text[256];
    std::snprintf(text, sizeof text, "relMSE %.3g, means %.4f %.4f %.4f (reference %.4f %.4f %.4f)",
                  e.relmse, e.test_means[0], e.test_means[1], e.test_means[2], e.reference_means[0],
                  e.reference_means[1], e.reference_means[2]);
    return text;
}

}  // namespace rc::test
