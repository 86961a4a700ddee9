// Temporal radiance caching of the glossy lobes (`--method rc --temporal`; Gautron, Bouatouch and
// Pattanaik 2006, §3 and §6: the same temporal weights and gradients for radiance records as for
// irradiance records; docs/temporal-caching.md): radiance records keep their place across frames,
// each serving the frames its lifespan allows, its change to the next frame estimated by
// reprojecting its hemisphere's uniform cells (TcRadianceReprojection). Driven by temporal
// irradiance caching's two passes (TemporalIrradianceCache): pass 1 places a frame's radiance
// records once its irradiance records are placed (their first level is what the radiance records'
// hemisphere rays read), ahead of shading by the longest lifespan when the gradients are
// interpolated; pass 2 shades the frame from the records serving it, their values at that frame.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "methods/caching/glossy_cache.h"
#include "methods/frame_scene.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/radiance_cache/tc_radiance_reprojection.h"
#include "methods/radiance_cache/temporal_radiance_record.h"
#include "methods/temporal/tc_motion.h"
#include "methods/temporal/temporal_glossy.h"
#include "methods/temporal/temporal_glossy_set.h"
#include "methods/temporal/temporal_options.h"

namespace rc {

class TemporalRadianceCache final : public TemporalGlossySetRecords {
   public:
    TemporalRadianceCache(RadianceCacheOptions options, TemporalOptions temporal, int first_frame,
                          int last_frame);

    // Pass 1 at `frame` (in order), once its irradiance records are placed: `params` and `camera`
    // the irradiance cache's, `diffuse` its first level, `motion` the changes to the next frame.
    void place_frame(const FrameScene& frame, const TcMotion& motion,
                     const shared::IcParams& params, const shared::CameraParams& camera,
                     const RadianceSource& diffuse) override;
    // Pass 2: the glossy cache that shades `frame` (placed before): the records serving it, their
    // payloads at that frame.
    std::unique_ptr<GlossyCache> shading(const FrameScene& frame) const override;

   private:
    // The records serving `frame` (indices appended to *serving) in a store of order `order`,
    // and those whose lifespan ends at `frame` (appended to *expired).
    RecordStore serving_store(int frame, int order, std::vector<size_t>* serving,
                              std::vector<size_t>* expired) const;

    RadianceCacheOptions options_;
    int order_ = 1;  // of the records (the BRDF tables', the same every frame)
    std::shared_ptr<const BrdfTables> tables_;  // built at the first frame, shared by the rest
};

}  // namespace rc
