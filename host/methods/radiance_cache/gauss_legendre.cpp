#include "methods/radiance_cache/gauss_legendre.h"

#include <cmath>
#include <numbers>

#include "util/error.h"

namespace rc {

QuadratureRule gauss_legendre(int n, double a, double b) {
    if (n < 1) {
        throw Error("Gauss-Legendre rule of " + std::to_string(n) + " points (at least 1)");
    }
    QuadratureRule rule;
    rule.nodes.resize(n);
    rule.weights.resize(n);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p_prev = 1.0;
            double p = x;
            for (int k = 1; k < n; ++k) {
                const double next = ((2.0 * k + 1.0) * x * p - k * p_prev) / (k + 1.0);
                p_prev = p;
                p = next;
            }
            derivative = n * (x * p - p_prev) / (x * x - 1.0);
            const double step = p / derivative;
            x -= step;
            if (std::abs(step) < 1e-15) {
                break;
            }
        }
        // Descending roots from the estimate; stored ascending.
        const double half = 0.5 * (b - a);
        rule.nodes[n - 1 - i] = 0.5 * (a + b) + half * x;
        rule.weights[n - 1 - i] = half * 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return rule;
}

}  // namespace rc
