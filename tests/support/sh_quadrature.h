// Host-side pieces of the spherical-harmonics tests: product quadrature over the sphere and the
// hemisphere (Gauss-Legendre in cos(theta), midpoint in phi), random directions and rotations,
// and the device's basis functions at given directions (rc_basis_probe).
#pragma once

#include <random>
#include <vector>

#include "device/context.h"
#include "scene/material.h"
#include "shared/types.h"

namespace rc::test {

struct DirectionQuadrature {
    std::vector<shared::float4> directions;
    std::vector<double> weights;
};

// theta_nodes Gauss-Legendre nodes in z over [z_min, 1] times phi_nodes midpoints in phi: exact
// for polynomials of degree <= 2 theta_nodes - 1 in z times trigonometric polynomials of degree
// < phi_nodes in phi. z_min = -1: the sphere; 0: the upper hemisphere.
DirectionQuadrature product_quadrature(double z_min, int theta_nodes, int phi_nodes);

// Legendre polynomial P_l(x), by the three-term recurrence in double.
double legendre(int l, double x);

// A uniformly distributed unit direction.
shared::float4 random_direction(std::mt19937& rng);

// A uniformly distributed rotation (from a normalized Gaussian quaternion), row-major 3x3.
std::vector<double> random_rotation(std::mt19937& rng);

// The device's basis functions (RC_BASIS_SH or RC_BASIS_HSH) of order `order` at `directions`:
// direction i's at [i * order^2, (i + 1) * order^2).
std::vector<float> device_basis(Context& context, int basis, int order,
                                const std::vector<shared::float4>& directions);

// The directional albedo of `material` at w_o over the hemisphere of a record whose frame
// `rotation` (row-major 3x3, record frame -> the frame of w_o) reaches: the integral of f cos over
// the directions w_i with (R^T w_i).z > 0, by Gauss-Legendre 96 x midpoint 192 of the material's
// own evaluation (kernels/material_probe.cl, material_eval_probe; the red channel). The identity:
// the albedo over w_o's own hemisphere.
double record_hemisphere_albedo(Context& context, const Material& material, shared::float4 wo,
                                const std::vector<double>& rotation = {1, 0, 0, 0, 1, 0, 0, 0, 1});

}  // namespace rc::test
