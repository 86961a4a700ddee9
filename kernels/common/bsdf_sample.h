// What sampling a BSDF returns (kernels/common/material.h and the lobes it dispatches to).
#pragma once

#include "shared/types.h"

// A direction sampled from a BSDF for a given wo, in the local shading frame (z = shading normal
// on wo's side; wi.z < 0: a transmission). f |wi.z| / pdf is the path throughput's factor for
// every lobe: for a delta lobe (a smooth mirror, a smooth dielectric) f holds the lobe's weight
// over |wi.z| and pdf the probability of choosing that lobe, as pbrt-v4 stores them (pbrt-v4
// §9.1.2, BSDFSample).
typedef struct BsdfSample {
    float3 wi;
    float3 f;
    float pdf;
    float eta;   // the relative index of refraction a transmission crossed (1 for a reflection)
    bool delta;  // from a delta lobe: light sampling cannot find wi, so MIS gives it weight 1
} BsdfSample;

// The mirror direction of w about the local normal.
RC_FUNC float3 rc_reflect_local(float3 w) { return (float3)(-w.x, -w.y, w.z); }

// The mirror direction of wo about the unit microfacet normal m.
RC_FUNC float3 rc_reflect_about(float3 wo, float3 m) { return 2.0f * dot(wo, m) * m - wo; }
