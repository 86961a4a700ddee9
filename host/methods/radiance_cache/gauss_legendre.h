// Gauss-Legendre quadrature: the rule radiance caching's BRDF tables integrate with in
// cos(theta) (kernels/radiance_cache/rc_brdf_table.h), and the tests' host-side quadrature.
#pragma once

#include <vector>

namespace rc {

struct QuadratureRule {
    std::vector<double> nodes;
    std::vector<double> weights;
};

// The n-point rule on [a, b] (n >= 1): exact for polynomials of degree <= 2n - 1. Nodes are the
// roots of the Legendre polynomial P_n, found by Newton's method from Tricomi's estimate
// cos(pi (i + 3/4) / (n + 1/2)), P_n and P_n' by the three-term recurrence
// (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}; weights 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz
// and Stegun 25.4.29), scaled to [a, b]. Ascending nodes.
QuadratureRule gauss_legendre(int n, double a = -1.0, double b = 1.0);

}  // namespace rc
