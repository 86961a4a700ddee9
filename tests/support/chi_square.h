// Pearson's chi-square goodness-of-fit test of sample counts against expected counts.
#pragma once

#include <string>
#include <vector>

namespace rc::test {

struct ChiSquareResult {
    double statistic = 0.0;
    int degrees_of_freedom = 0;
    double p_value = 1.0;  // probability of a statistic at least this large if the fit is right
    std::string summary() const;
};

// Bins whose expected count is below `min_expected` are pooled into one (the usual rule of five);
// returns the statistic, its degrees of freedom (bins - 1) and the p-value (Wilson-Hilferty
// normal approximation of the chi-square distribution, accurate for the dozens to hundreds of
// degrees of freedom used here).
ChiSquareResult chi_square_test(const std::vector<double>& observed,
                                const std::vector<double>& expected, double min_expected = 5.0);

}  // namespace rc::test
