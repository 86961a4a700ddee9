#include "chi_square.h"

#include <cmath>
#include <cstdio>

namespace rc::test {

std::string ChiSquareResult::summary() const {
    char text[128];
    std::snprintf(text, sizeof text, "chi2 = %.1f, dof = %d, p = %.3g", statistic,
                  degrees_of_freedom, p_value);
    return text;
}

ChiSquareResult chi_square_test(const std::vector<double>& observed,
                                const std::vector<double>& expected, double min_expected) {
    ChiSquareResult result;
    double pooled_observed = 0.0;
    double pooled_expected = 0.0;
    int bins = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < min_expected) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        const double d = observed[i] - expected[i];
        result.statistic += d * d / expected[i];
        ++bins;
    }
    if (pooled_expected > 0.0) {
        const double d = pooled_observed - pooled_expected;
        result.statistic += d * d / pooled_expected;
        ++bins;
    } else if (pooled_observed > 0.0) {
        // Samples where the density says none can be.
        result.statistic = INFINITY;
    }
    result.degrees_of_freedom = std::max(1, bins - 1);
    const double k = result.degrees_of_freedom;
    // Wilson-Hilferty: (X / k)^(1/3) is nearly normal with mean 1 - 2/(9k), variance 2/(9k).
    const double z =
        (std::cbrt(result.statistic / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
    result.p_value = 0.5 * std::erfc(z / std::sqrt(2.0));
    return result;
}

}  // namespace rc::test
