// SDRC (DESIGN.md §6.5) as an entry of the glossy-cache registry (methods/caching/glossy_caches.h):
// `--method ic --glossy sdrc`, its options --method sdrc's defaults with the irradiance records'
// shared settings (share_record_settings), as --method sdrc makes them.
#include <memory>

#include "methods/caching/glossy_caches.h"
#include "methods/caching/glossy_method.h"
#include "methods/sdrc/sdrc_cache.h"

namespace rc {

GlossyCacheEntry sdrc_glossy_entry() {
    GlossyCacheEntry entry;
    entry.name = "sdrc";
    entry.layer = "sdrc-hits";
    entry.stats_key = "sdrc";
    entry.create = make_glossy_cache<SdrcCache, SdrcOptions>;
    entry.programs = {{"sdrc/sdrc.cl", ""},
                      {"sdrc/sdrc_trace.cl", radiance_source_define(RC_RADIANCE_RECORDS)},
                      {"caching/glossy_placement.cl", ""}};
    // SdrcCache::glossy_samples: the queries and glossy samples.
    entry.bytes = {sizeof(shared::RcQuery), sizeof(shared::RcGlossySample), 0};
    entry.excludes = "the SDRC records, their batches and their L-trees";
    return entry;
}

}  // namespace rc
