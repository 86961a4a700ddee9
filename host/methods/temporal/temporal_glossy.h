// What temporal caching asks of a glossy cache that keeps its records across frames (`--method rc
// --temporal`: radiance_cache/temporal_radiance_cache.h): TemporalIrradianceCache drives it
// through its two passes (Gautron, Bouatouch and Pattanaik 2006, §3: the temporal weights and
// gradients serve any record with a payload). Pass 1 places a frame's glossy records once the
// frame's irradiance records are placed (their first level is what the glossy records' rays
// read); pass 2 shades the frame from the records serving it.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "methods/frame_scene.h"
#include "methods/glossy_cache.h"
#include "methods/radiance_source.h"
#include "methods/temporal/tc_motion.h"
#include "shared/types.h"

namespace rc {

class TemporalGlossyRecords {
   public:
    virtual ~TemporalGlossyRecords() = default;
    // Pass 1 at `frame` (in order), once its irradiance records are placed: `params` and `camera`
    // the irradiance cache's, `diffuse` its first level, `motion` the changes to the next frame.
    virtual void place_frame(const FrameScene& frame, const TcMotion& motion,
                             const shared::IcParams& params, const shared::CameraParams& camera,
                             const RadianceSource& diffuse) = 0;
    // Pass 2: the glossy cache that shades `frame` (placed before): the records serving it, their
    // payloads at that frame.
    virtual std::unique_ptr<GlossyCache> shading(const FrameScene& frame) const = 0;
    // The statistics of `frame`'s placement.
    virtual nlohmann::json frame_stats(int frame) const = 0;
};

}  // namespace rc
