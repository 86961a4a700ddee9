// The material test kernels (kernels/material_probe.cl) on the tests' device: a material's BSDF
// value and pdf at given directions, and directions sampled from it; and direction grids with
// their solid angles for the integrals the material tests take.
#pragma once

#include <vector>

#include "shared/types.h"

namespace rc::test {

// For each direction wi: (f(wo, wi), pdf(wo, wi)) in (xyz, w).
std::vector<shared::float4> material_values(const shared::Material& material, shared::float4 wo,
                                            const std::vector<shared::float4>& directions);

struct MaterialSamples {
    std::vector<shared::float4> directions;  // xyz: wi, w: pdf (-1: failed)
    std::vector<shared::float4> values;      // xyz: f, w: 1 for a delta lobe
};

MaterialSamples material_samples(const shared::Material& material, shared::float4 wo, size_t count,
                                 unsigned seed);

// Directions at the centres of a theta x phi grid from the pole to theta_max (midpoint rule),
// with their solid angles.
struct DirectionGrid {
    std::vector<shared::float4> directions;
    std::vector<double> weights;
};

DirectionGrid direction_grid(int theta_steps, int phi_steps, double theta_max);

}  // namespace rc::test
