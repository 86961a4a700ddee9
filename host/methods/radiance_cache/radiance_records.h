// Radiance caching's records in the shared record store (host/methods/caching/; DESIGN.md §6.4):
// the payload of 9 n^2 floats (kernels/shared/records.h: the r, g, b coefficient vectors of
// order n, then their x and y translational gradients per channel), the radius limit its
// gradients set, and the payloads as the kernels read them.
#pragma once

#include <vector>

#include "methods/caching/cache_file.h"
#include "methods/caching/record_store.h"
#include "scene/scene.h"

namespace rc {

// Floats in a record's payload at order n: 3 n^2 coefficients and 6 n^2 gradient entries.
size_t radiance_payload_floats(int order);

// An empty store of radiance records of order n.
RecordStore radiance_store(float accuracy, int order);

// The gradient limit on R from the band-0 coefficient (the mean incoming radiance, luminance):
// lambda_0 / |grad lambda_0|, as irradiance caching limits by E / |grad E| (course, "Gradient
// Limit on Record Spacing"); infinite where there is no gradient or no radiance.
float radiance_radius_limit(const std::vector<float>& payload, int order);

// Every record's payload as the kernels read it, record after record: gradients scaled by
// store.gradient_scale(i), so extrapolation over a radius the [R_min, R_max] clamp raised stays
// as bounded as over R.
std::vector<float> device_radiance_payloads(const RecordStore& store, int order);

// The method tag of radiance records in cache files.
inline constexpr const char* kRadianceMethodTag = "radiance";

// The cache-file key of radiance records of order n for this scene and accuracy (one level).
CacheFileKey radiance_cache_key(const Scene& scene, float accuracy, int order);

}  // namespace rc
