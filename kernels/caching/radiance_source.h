// "The radiance beyond the first bounce" that a caching method's hemisphere rays read (DESIGN.md
// §2, §6.2 step 3), from the source the program is built for (-DRC_RADIANCE_SOURCE, one of
// shared/radiance_sources.h; path-traced continuation without it). Every source defines
//   RadianceSource                  what it reads;
//   RC_RADIANCE_SOURCE_PARAMETERS   its kernel parameters, each followed by a comma (bound on the
//                                   host by the source's RadianceSource::set_kernel_args);
//   RC_RADIANCE_SOURCE_DATA()       the RadianceSource those parameters make;
//   rc_source_radiance(scene, source, ray, rng, count_emission, bounces, max_depth, rr_depth)
//                                   the light arriving along `ray` (bounces: those its path made
//                                   before), as a SourceSample.
#pragma once

// The host's include expansion (host/device/kernel_sources.h) takes each file once, where it first
// appears, even inside a branch of the choice below that the compiler then skips: include this
// header after the program's other headers, and it includes the common ones the sources need
// before the choice.
#include "common/cached_radiance.h"
#include "common/path_radiance.h"
#include "shared/radiance_sources.h"

#ifndef RC_RADIANCE_SOURCE
#define RC_RADIANCE_SOURCE RC_RADIANCE_PATH
#endif

// What a ray brings back from a source.
typedef struct SourceSample {
    float3 radiance;
    float distance;  // to the ray's first hit; infinite for a miss
    uint rays;       // traced on its behalf
} SourceSample;

#if RC_RADIANCE_SOURCE == RC_RADIANCE_RECORDS
#include "caching/record_level_source.h"
#elif RC_RADIANCE_SOURCE == RC_RADIANCE_GRID
#include "common/ivg_source.h"
#else

// Path-traced continuation: nothing to read.
typedef struct RadianceSource {
    int unused;
} RadianceSource;

#define RC_RADIANCE_SOURCE_PARAMETERS
#define RC_RADIANCE_SOURCE_DATA() \
    { 0 }

// The path tracer's estimate along the ray; the emission of its first hit only if
// count_emission.
RC_FUNC SourceSample rc_source_radiance(const SceneData* scene, const RadianceSource* source,
                                        Ray ray, RngStream* rng, bool count_emission, int bounces,
                                        int max_depth, int rr_depth) {
    const PathSample s =
        rc_path_radiance(scene, ray, rng, bounces, max_depth, rr_depth, count_emission);
    const SourceSample r = {s.radiance, s.distance, s.rays};
    return r;
}

#endif
