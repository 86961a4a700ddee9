// How finely pbrt's quadrics are tessellated into triangles: a full turn is cut into
// kFullTurnSegments straight segments, so a circle of radius r is approximated by a polygon whose
// edges stray at most r (1 - cos(pi / N)) = 7.5e-5 r from it (N = 256) and whose area falls
// short by 1 - sin(2 pi / N) / (2 pi / N) = 1.004e-4 of the circle's: below a pixel at 10 000
// pixels across the circle, and below the noise of every image the tests and references measure.
#pragma once

#include <algorithm>
#include <cmath>

namespace rc {

constexpr int kFullTurnSegments = 256;

// The segments of an arc of `degrees` (in (0, 360]): the full turn's density, at least 2.
inline int arc_segments(float degrees) {
    const int segments = static_cast<int>(std::ceil(kFullTurnSegments * degrees / 360.0f));
    return std::max(2, segments);
}

}  // namespace rc
