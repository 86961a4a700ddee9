#include "app/recorded_files.h"

#include <OpenImageIO/hash.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace rc {

std::string bytes_digest(std::string_view bytes) {
    char text[17];
    std::snprintf(
        text, sizeof text, "%016llx",
        static_cast<unsigned long long>(OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size())));
    return text;
}

uint64_t RecordedFiles::bytes_fingerprint(const std::string& bytes) {
    return OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size());
}

std::string RecordedFiles::content_digest() const {
    std::vector<std::pair<std::filesystem::path, uint64_t>> files;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        files = fingerprints_;
    }
    // Each file's role: its path relative to the scene file's folder (the first file read).
    const std::filesystem::path base =
        files.empty()
            ? std::filesystem::path()
            : std::filesystem::absolute(files.front().first).lexically_normal().parent_path();
    std::vector<uint64_t> sorted;
    for (const auto& [path, fingerprint] : files) {
        const std::string role = std::filesystem::absolute(path)
                                     .lexically_normal()
                                     .lexically_relative(base)
                                     .generic_string();
        const std::string keyed = role + '\0' + std::to_string(fingerprint);
        sorted.push_back(bytes_fingerprint(keyed));
    }
    // Sorted, so that the order of the reads does not count; a file read twice (an include named
    // twice) counts twice, as it does for the loader.
    std::sort(sorted.begin(), sorted.end());
    return bytes_digest(std::string_view(reinterpret_cast<const char*>(sorted.data()),
                                         sorted.size() * sizeof(uint64_t)));
}

}  // namespace rc
