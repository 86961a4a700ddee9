// The records of a glossy cache across the frames of temporal caching, whatever their payload
// (`--method rc --temporal`, `--method sdrc --temporal`; Gautron, Bouatouch and Pattanaik 2006):
// which records serve a frame and which expire there (§4.2: each serves the frames its lifespan
// allows), the new records' lifespans from their reprojected change (eqs. 9-12), replacements
// linked to the records they replace (§5 "Replacement/Deletion Method"), each frame's serving
// records as placement left them, and their payloads at a frame (the temporal gradients, §4.4).
// The cache itself places and computes its records (TemporalGlossyRecords, temporal_glossy.h).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "methods/caching/record_store.h"
#include "methods/temporal/temporal_glossy.h"
#include "methods/temporal/temporal_glossy_record.h"
#include "methods/temporal/temporal_options.h"

namespace rc {

// What pass 1 did with a glossy cache's records at one frame.
struct TemporalGlossyFrameStats {
    size_t reused = 0;      // records of earlier frames still serving
    size_t recomputed = 0;  // expired records computed again in their place
    size_t dropped = 0;     // expired records that no longer served the image
    size_t created = 0;     // new records where the image was not covered
    size_t records = 0;     // serving this frame
    double mean_new_lifespan = 0.0;
    uint64_t record_rays = 0;
    double placement_seconds = 0.0;
};

class TemporalGlossySet {
   public:
    // A record serving a frame, as the store held it at the end of that frame's placement.
    struct Serving {
        size_t record = 0;  // index into records()
        shared::Record shared{};
        RecordHostData host{};
    };

    // Frames first_frame .. last_frame, placed in order.
    TemporalGlossySet(TemporalOptions temporal, int first_frame, int last_frame);

    // The records serving `frame` (indices appended to *serving) and those whose lifespan ends
    // at `frame` (appended to *expired).
    void select(int frame, std::vector<size_t>* serving, std::vector<size_t>* expired) const;
    // Of `expired`, the records whose own surface stays (the others are dropped, not replaced).
    std::vector<size_t> staying(const std::vector<size_t>& expired) const;
    // The records computed again in their place: those of `candidates` (staying()) a served
    // query still weighs (`used`, one flag each; the report's §5), with their sites and streams.
    struct Replacements {
        std::vector<size_t> records;
        std::vector<shared::RcQuery> sites;
        std::vector<unsigned> streams;
    };
    Replacements replacements(const std::vector<size_t>& candidates,
                              const std::vector<uint8_t>& used) const;
    // After placement at `frame`: the serving records as neighbor clamping left them in `placed`
    // (its first serving.size() records) and the new ones (the rest, observed as `carried`, with
    // `payloads`), lifespans by their change over the payloads' first 3 x `per_channel` floats;
    // the first replaced.size() of them replace those. `expired`: how many expired at `frame`.
    // Returns the frame's statistics, the rays and seconds left to the caller.
    TemporalGlossyFrameStats& adopt(int frame, const RecordStore& placed,
                                    const std::vector<size_t>& serving, size_t expired,
                                    std::vector<CarriedGlossyRecord> carried,
                                    std::vector<std::vector<float>> payloads,
                                    const std::vector<size_t>& replaced, size_t per_channel);

    // The records serving `frame` (placed before: Error otherwise).
    const std::vector<Serving>& serving(int frame) const;
    // Record `record`'s payload at `frame` by the temporal gradients (glossy_temporal_payload).
    std::vector<float> payload_at(size_t record, int frame) const;
    // The statistics of `frame`'s placement.
    nlohmann::json frame_stats(int frame) const;

    // Every record computed so far, in creation order.
    const std::vector<TemporalGlossyRecord>& records() const { return records_; }
    // The random stream of the next new record.
    unsigned next_stream() const { return next_stream_; }
    void set_next_stream(unsigned stream) { next_stream_ = stream; }

   private:
    TemporalOptions temporal_;
    int first_frame_;
    int last_frame_;
    unsigned next_stream_ = 0;
    std::vector<TemporalGlossyRecord> records_;
    std::vector<std::vector<Serving>> serving_;          // per frame from first_frame_
    std::vector<TemporalGlossyFrameStats> frame_stats_;  // per frame from first_frame_
};

// A glossy cache's records across frames (TemporalGlossyRecords) kept in a TemporalGlossySet: the
// statistics and the records are the set's; placement and shading are the deriving cache's.
class TemporalGlossySetRecords : public TemporalGlossyRecords {
   public:
    nlohmann::json frame_stats(int frame) const override { return set_.frame_stats(frame); }
    // Every record computed so far, in creation order (tests).
    const std::vector<TemporalGlossyRecord>& records() const { return set_.records(); }

   protected:
    TemporalGlossySetRecords(TemporalOptions temporal, int first_frame, int last_frame)
        : set_(temporal, first_frame, last_frame) {}

    TemporalGlossySet set_;  // the records across frames
};

}  // namespace rc
