// Radiance caching (DESIGN.md §6.4) as an entry of the glossy-cache registry
// (methods/caching/glossy_caches.h): `--method ic --glossy rc`, its options --method rc's defaults
// with the irradiance records' shared settings (share_record_settings), as --method rc makes them.
#include "methods/caching/glossy_caches.h"
#include "methods/caching/glossy_method.h"
#include "methods/radiance_cache/radiance_cache.h"
#include "shared/sh_rotation_zxz.h"

namespace rc {

GlossyCacheEntry radiance_cache_glossy_entry() {
    GlossyCacheEntry entry;
    entry.name = "rc";
    entry.layer = "rc-order";
    entry.stats_key = "radiance_cache";
    entry.create = make_glossy_cache<RadianceCache, RadianceCacheOptions>;
    entry.programs = {
        {"radiance_cache/radiance_cache.cl", ""},
        {"radiance_cache/rc_cache.cl", ""},
        {"radiance_cache/rc_record_cells.cl", radiance_source_define(RC_RADIANCE_RECORDS)},
        {"caching/glossy_placement.cl", ""}};
    // RadianceCache::glossy_samples: the queries and glossy samples, with the splat's x90 table
    // and counter.
    entry.bytes = {
        sizeof(shared::RcQuery), sizeof(shared::RcGlossySample),
        buffer_bytes(RC_SH_X90_TABLE_SIZE, sizeof(float)) + buffer_bytes(1, sizeof(unsigned))};
    entry.excludes = "the radiance records, their batches and the BRDF tables";
    return entry;
}

}  // namespace rc
