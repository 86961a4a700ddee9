// Temporal radiance caching (Gautron, Bouatouch and Pattanaik 2006; DESIGN.md §6.6;
// `--method ic --temporal`; docs/temporal-caching.md) for irradiance caching: records keep their
// place across the frames of an animation and serve the frames their temporal weight allows (the
// report's §4.2), each estimating its own change by reprojection (§4.3, TemporalReprojection).
// A first-level record (the camera's) that expires is computed again in its place when it still
// serves the image and dropped otherwise (§5 "Replacement/Deletion Method"); between, its value
// follows temporal gradients (§4.4). Deeper levels' records (--ic-bounces) live by the same
// lifespans and are dropped when they expire: new ones are placed where a new record's rays need
// them. Placement (pass 1) runs ahead of shading (pass 2) by the longest lifespan when the
// gradients are interpolated, so every record's replacement is known before the frames it blends
// over are shaded; frames are rendered in order.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "methods/caching/cache_pipeline.h"
#include "methods/method.h"
#include "methods/temporal/tc_reprojection.h"
#include "methods/temporal/temporal_glossy.h"
#include "methods/temporal/temporal_options.h"
#include "methods/temporal/temporal_record.h"

namespace rc {

// What placement did at one deeper cache level at one frame.
struct TemporalLevelStats {
    size_t reused = 0;
    size_t created = 0;
    size_t dropped = 0;
    size_t on_moving_surfaces = 0;   // of the created: on triangles that move (lifespan 1)
    double mean_new_lifespan = 0.0;  // of the created
};

// What placement did at one frame (pass 1); the counts are the first level's.
struct TemporalFrameStats {
    size_t reused = 0;               // records of earlier frames still serving
    size_t recomputed = 0;           // expired records computed again in their place
    size_t dropped = 0;              // expired records that no longer served the image
    size_t created = 0;              // new records where the image was not covered
    size_t on_moving_surfaces = 0;   // of the created and recomputed: on triangles that move
    size_t records = 0;              // serving this frame
    size_t moving_primitives = 0;    // triangles that move before the next frame
    double mean_new_lifespan = 0.0;  // of the records computed at this frame
    uint64_t record_rays = 0;
    double placement_seconds = 0.0;          // pass 1: G-buffer, reprojection, placement, records
    double reprojection_seconds = 0.0;       // of which the reprojections (both with departure)
    double usage_seconds = 0.0;              // of which the test of expired records' use
    PipelineStats placement;                 // irradiance caching's figures of pass 1
    std::vector<TemporalLevelStats> deeper;  // levels 1, 2, ...
};

class TemporalIrradianceCache {
   public:
    // Frames first_frame .. first_frame + frame_count - 1 will be asked for, in order.
    TemporalIrradianceCache(PipelineSettings ic, TemporalOptions temporal, int first_frame,
                            int frame_count);
    // With `glossy` (`--method rc --temporal`), the glossy lobes come from its radiance records:
    // placed in pass 1 after each frame's irradiance records, read in pass 2.
    void set_glossy(TemporalGlossyRecords* glossy) { glossy_ = glossy; }

    FrameResult render_frame(const FrameScene& frame, const FrameHooks& hooks);

    // Every record of cache level `level` computed so far, in creation order (tests).
    const std::vector<TemporalRecord>& records(int level = 0) const {
        return levels_.at(static_cast<size_t>(level)).records;
    }

   private:
    // A record serving a frame, as the store held it at the end of that frame's placement.
    struct Serving {
        size_t record = 0;  // index into the first level's records
        shared::Record shared{};
        RecordHostData host{};
    };
    // Pass 1 through frame `last`, from the first frame not yet placed (other frames through
    // hooks.visit_frame).
    void place_through(int last, const FrameScene& frame, const FrameHooks& hooks);
    // Pass 1 at one frame.
    void place_frame(const FrameScene& frame);
    // Per primitive: 1 where it moves into or out of the frame `reprojection` starts from (the
    // moves into it remembered from the frame placed before).
    std::vector<uint8_t> moving_into_or_out(const TemporalReprojection& reprojection);
    // With --temporal-lifespan departure, the reprojection of `frame`'s new records two frames
    // ahead; else null.
    std::unique_ptr<TemporalReprojection> two_frames_ahead(const FrameScene& frame);
    // A cache level's records across frames.
    struct Level {
        std::vector<TemporalRecord> records;
        uint32_t next_stream = 0;  // random stream of its next record
    };
    // The records of `level` serving at `frame` (indices into its records, appended to *serving)
    // in a store, and those whose lifespan ends at `frame` (appended to *expired).
    RecordStore serving_store(int level, int frame, std::vector<size_t>* serving,
                              std::vector<size_t>* expired) const;
    // The first level's expired records that still serve the image of `cache`'s G-buffer.
    std::vector<size_t> still_used(CachePipeline& cache, const std::vector<size_t>& expired);
    // After placement at `frame`: `level`'s serving records as neighbor clamping left them in
    // `placed` (its first serving.size() records), and its new records (the rest, observed as
    // `carried`) with their lifespans; the new records from `replaced.size()` on are
    // replacements of those. `ahead`: with --temporal-lifespan departure at the first level, the
    // new records' estimates two frames ahead (as `carried`), else empty. Returns the mean
    // lifespan of the new records.
    double adopt(int level, int frame, const RecordStore& placed,
                 const std::vector<size_t>& serving, const std::vector<CarriedRecord>& carried,
                 const std::vector<CarriedRecord>& ahead, const std::vector<size_t>& replaced,
                 bool still);
    // A new record's lifespan by the chosen rule (`ahead`: its estimate two frames ahead, with
    // --temporal-lifespan departure at the first level; else null); `still`: nothing moves or
    // changes light from `frame` to the next, so that without --temporal-max-frames the record
    // serves to the clip's end or until something moves (sets r->until_motion).
    int new_lifespan(TemporalRecord* r, const CarriedRecord* ahead, int frame, bool still) const;
    // Something moves or changes light from `frame` to the next: every record serving until
    // motion expires at the next frame (replaced or dropped there as any other).
    void end_still_records(int frame);
    // Pass 2 at one frame: the image from the records serving it, their values at that frame.
    FrameResult shade_frame(const FrameScene& frame);

    PipelineSettings ic_;
    TemporalOptions temporal_;
    int first_frame_;
    int last_frame_;
    int placed_until_;            // the last frame placed (pass 1)
    int shaded_until_;            // the last frame shaded (pass 2)
    std::optional<Scene> next_;   // the scene posed at the frame after the one being placed
    std::optional<Scene> ahead_;  // and two frames after it (--temporal-lifespan departure)
    // Per primitive: 1 where it moved from the frame placed last to the one after it.
    std::vector<uint8_t> moved_before_;
    std::vector<Level> levels_;                    // 0: the camera's
    std::vector<std::vector<Serving>> serving_;    // per frame from first_frame_: first level
    std::vector<TemporalFrameStats> frame_stats_;  // per frame from first_frame_
    TemporalGlossyRecords* glossy_ = nullptr;
};

}  // namespace rc
