// Record placement of the glossy caches (radiance caching, DESIGN.md §6.4; SDRC, §6.5): the camera
// samples a cache serves (RcQuery.order > 0), and records placed where they are not covered,
// coarse to fine as irradiance caching places its own: the first camera sample of every
// stride-th pixel of every stride-th row for strides 16, 8, 4, 2, then every served sample until
// all are covered. Uncovered candidates are thinned by their smallest influence radius before the
// method computes its records at them. Deterministic: the candidates are kept in index order.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "device/buffer.h"
#include "device/context.h"
#include "methods/caching/cache_pipeline.h"
#include "methods/caching/record_store.h"
#include "shared/radiance_cache.h"

namespace rc {

// The coarsest placement stride at which camera sample i (entry pixel * spp + s of an image
// `width` pixels wide) is a candidate: the largest of 16, 8, 4, 2 whose grid holds its pixel when
// it is its pixel's first sample, else 1. A sample is a candidate at every stride up to it.
int first_candidate_stride(uint32_t i, uint32_t width, uint32_t spp);

// The random streams of `count` new records: *next, *next + 1, ..., *next advanced past them.
std::vector<unsigned> next_streams(size_t count, unsigned* next);

struct GlossyPlacementStats {
    std::vector<PlacementPass> passes;  // level 0 only
    size_t glossy_samples = 0;          // camera samples on a specular lobe the cache serves
    size_t fallback_samples = 0;        // of those, left to Monte Carlo (order 0)
    double placement_seconds = 0.0;     // coverage tests and candidate thinning
    double record_seconds = 0.0;        // in the method's record computation
};

class GlossyPlacement {
   public:
    explicit GlossyPlacement(Context& context);

    // The method's records at `sites` (in order), inserted into the store place() was given.
    using AddRecords = std::function<void(const std::vector<shared::RcQuery>& sites)>;

    // Places records for the camera-sample queries of an image `width` pixels wide with `spp`
    // samples per pixel (entry pixel * spp + s), until every served query is covered by a record
    // of `store` (weights at `accuracy`); min_spacing bounds the candidates' thinning.
    void place(const Buffer<shared::RcQuery>& queries, const RecordStore& store, uint32_t width,
               uint32_t spp, Spacing min_spacing, const AddRecords& add_records,
               GlossyPlacementStats* stats);

    // Per record of `store`: 1 where a served query weighs it positively (temporal caching's
    // test of the records still in use, the report's §5 "Replacement/Deletion Method").
    std::vector<uint8_t> records_used(const Buffer<shared::RcQuery>& queries,
                                      const RecordStore& store);

    // After place(): the served queries' indices (ascending) and their host copies.
    const std::vector<uint32_t>& served() const { return served_; }
    const std::vector<shared::RcQuery>& copies() const { return copies_; }

   private:
    void select_served(const Buffer<shared::RcQuery>& queries, GlossyPlacementStats* stats);
    const shared::RcQuery& copy(uint32_t index) const;
    // The indices among `candidates` that no record of `store` covers, ascending.
    std::vector<uint32_t> uncovered(const Buffer<shared::RcQuery>& queries,
                                    const RecordStore& store,
                                    const std::vector<uint32_t>& candidates);
    // Places records until the candidates are covered (or one pass at coarse strides).
    void cover(const Buffer<shared::RcQuery>& queries, const RecordStore& store,
               const std::vector<uint32_t>& candidates, int stride, bool until_covered,
               Spacing min_spacing, const AddRecords& add_records, GlossyPlacementStats* stats);

    Context& context_;
    Kernel served_kernel_;
    Kernel select_kernel_;
    Kernel uncovered_kernel_;
    Kernel used_kernel_;
    std::vector<uint32_t> served_;
    std::vector<shared::RcQuery> copies_;
};

}  // namespace rc
