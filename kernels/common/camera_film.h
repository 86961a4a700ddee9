// A pixel's sums in the caching methods' render passes (ic_shade, ivg_shade).
#pragma once

#include "common/cached_radiance.h"

// Adds a camera sample's light to a pixel's sums of beauty, direct, indirect, albedo and normal
// (sums[0] to sums[4]) and its rays to *rays. A sample whose radiance is NaN or infinite is
// dropped instead and counted in counters[1], with the smallest such pixel in counters[2].
// Returns whether the sample was added.
RC_FUNC bool rc_add_camera_sample(const CachedRadiance* l, float3 sums[5], uint* rays,
                                  __global uint* counters, uint pixel) {
    const float3 radiance = l->direct + l->indirect;
    *rays += l->rays;
    if (!all(isfinite(radiance))) {
        atomic_inc(&counters[1]);
        atomic_min(&counters[2], pixel);
        return false;
    }
    sums[0] += radiance;
    sums[1] += l->direct;
    sums[2] += l->indirect;
    sums[3] += l->albedo;
    sums[4] += l->normal;
    return true;
}
