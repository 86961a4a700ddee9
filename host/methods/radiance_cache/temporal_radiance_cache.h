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

#include "methods/frame_scene.h"
#include "methods/glossy_cache.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "methods/radiance_cache/tc_radiance_reprojection.h"
#include "methods/radiance_cache/temporal_radiance_record.h"
#include "methods/temporal/tc_motion.h"
#include "methods/temporal/temporal_glossy.h"
#include "methods/temporal/temporal_options.h"

namespace rc {

// What pass 1 did with the radiance records at one frame.
struct TemporalRadianceFrameStats {
    size_t reused = 0;      // records of earlier frames still serving
    size_t recomputed = 0;  // expired records computed again in their place
    size_t dropped = 0;     // expired records that no longer served the image
    size_t created = 0;     // new records where the image was not covered
    size_t records = 0;     // serving this frame
    double mean_new_lifespan = 0.0;
    uint64_t record_rays = 0;
    double placement_seconds = 0.0;
};

class TemporalRadianceCache final : public TemporalGlossyRecords {
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
    // The statistics of `frame`'s placement.
    nlohmann::json frame_stats(int frame) const override;

    // Every record computed so far, in creation order (tests).
    const std::vector<TemporalRadianceRecord>& records() const { return records_; }

   private:
    struct Serving {
        size_t record = 0;  // index into records_
        shared::Record shared{};
        RecordHostData host{};
    };
    // The records serving `frame` (indices appended to *serving) in a store of order `order`,
    // and those whose lifespan ends at `frame` (appended to *expired).
    RecordStore serving_store(int frame, int order, std::vector<size_t>* serving,
                              std::vector<size_t>* expired) const;
    // After placement at `frame`: the serving records as neighbor clamping left them in `placed`
    // (its first serving.size() records), the new ones (the rest, observed as `carried`) with
    // their lifespans, the first replaced.size() of them replacing those. Returns the mean
    // lifespan of the new records.
    double adopt(int frame, int order, const RecordStore& placed,
                 const std::vector<size_t>& serving, std::vector<CarriedRadianceRecord> carried,
                 const std::vector<size_t>& replaced);

    RadianceCacheOptions options_;
    TemporalOptions temporal_;
    int first_frame_;
    int last_frame_;
    unsigned next_stream_ = 0;
    int order_ = 1;  // of the records (the BRDF tables', the same every frame)
    std::shared_ptr<const BrdfTables> tables_;  // built at the first frame, shared by the rest
    std::vector<TemporalRadianceRecord> records_;
    std::vector<std::vector<Serving>> serving_;            // per frame from first_frame_
    std::vector<TemporalRadianceFrameStats> frame_stats_;  // per frame from first_frame_
};

}  // namespace rc
