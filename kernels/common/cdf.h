// Discrete distributions by their cumulative weights (cdf[count - 1] = 1): sampling an index and
// its probability.
#pragma once

#include "shared/types.h"

// Index i of the first cdf[i] > u in cdf[0, count), count >= 1 (cdf[count - 1] = 1).
RC_FUNC int rc_sample_cdf(RC_GLOBAL const float* cdf, int count, float u) {
    int low = 0;
    int high = count - 1;
    while (low < high) {
        const int middle = (low + high) / 2;
        if (cdf[middle] > u) {
            high = middle;
        } else {
            low = middle + 1;
        }
    }
    return low;
}

RC_FUNC float rc_cdf_probability(RC_GLOBAL const float* cdf, int i) {
    return cdf[i] - (i > 0 ? cdf[i - 1] : 0.0f);
}
