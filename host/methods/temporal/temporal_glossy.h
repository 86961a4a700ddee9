// What temporal caching asks of a glossy cache that keeps its records across frames (`--method rc
// --temporal`: radiance_cache/temporal_radiance_cache.h): TemporalIrradianceCache drives it
// through its two passes (Gautron, Bouatouch and Pattanaik 2006, §3: the temporal weights and
// gradients serve any record with a payload). Pass 1 places a frame's glossy records once the
// frame's irradiance records are placed (their first level is what the glossy records' rays
// read); pass 2 shades the frame from the records serving it.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "methods/caching/glossy_cache.h"
#include "methods/frame_scene.h"
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

// The glossy cache of one frame's shading in temporal caching: a `Cache` over the records serving
// the frame, which it owns; its layers, rays and record seconds are the cache's, its glossy
// samples the deriving class's.
template <class Cache>
class TemporalShadingCache : public GlossyCache {
   public:
    std::vector<FilmLayer> layers() const override { return cache_.layers(); }
    uint64_t rays() const override { return cache_.rays(); }
    double record_seconds() const override { return cache_.record_seconds(); }

   protected:
    template <class... Arguments>
    explicit TemporalShadingCache(Arguments&&... arguments)
        : cache_(std::forward<Arguments>(arguments)...) {}

    Cache cache_;
};

}  // namespace rc
