#include "app/recorded_files.h"

#include <OpenImageIO/hash.h>

#include <algorithm>
#include <cstdio>

namespace rc {

uint64_t RecordedFiles::bytes_fingerprint(const std::string& bytes) {
    return OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size());
}

std::string RecordedFiles::content_digest() const {
    std::vector<uint64_t> sorted;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        sorted = fingerprints_;
    }
    // Sorted, so that neither the paths nor the order of the reads count; a file read twice
    // (an include named twice) counts twice, as it does for the loader.
    std::sort(sorted.begin(), sorted.end());
    const uint64_t digest = OIIO::farmhash::Fingerprint64(
        reinterpret_cast<const char*>(sorted.data()), sorted.size() * sizeof(uint64_t));
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(digest));
    return text;
}

}  // namespace rc
