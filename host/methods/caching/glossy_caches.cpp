#include "methods/caching/glossy_caches.h"

// One line per glossy cache: X(entry function), defined in its method's folder as
// `GlossyCacheEntry <entry>_entry();`. The order is the layers' and the statistics'.
#define RC_GLOSSY_CACHES(X)  \
    X(radiance_cache_glossy) \
    X(sdrc_glossy)

namespace rc {

#define RC_DECLARE_GLOSSY_CACHE(entry) GlossyCacheEntry entry##_entry();
RC_GLOSSY_CACHES(RC_DECLARE_GLOSSY_CACHE)
#undef RC_DECLARE_GLOSSY_CACHE

const std::vector<GlossyCacheEntry>& glossy_cache_registry() {
#define RC_LIST_GLOSSY_CACHE(entry) entry##_entry(),
    static const std::vector<GlossyCacheEntry> caches = {RC_GLOSSY_CACHES(RC_LIST_GLOSSY_CACHE)};
#undef RC_LIST_GLOSSY_CACHE
    return caches;
}

const GlossyCacheEntry* find_glossy_cache(const std::string& name) {
    for (const GlossyCacheEntry& entry : glossy_cache_registry()) {
        if (entry.name == name) {
            return &entry;
        }
    }
    return nullptr;
}

std::string glossy_cache_names() {
    std::string names;
    for (const GlossyCacheEntry& entry : glossy_cache_registry()) {
        names += (names.empty() ? "" : ", ") + entry.name;
    }
    return names;
}

}  // namespace rc
