// Compiled program binaries on disk, keyed by a fingerprint of everything that determines them:
// the expanded source, the build options, the device name and the driver version. Each entry
// carries its key and a checksum; an entry that fails either check is ignored (and rebuilt by
// the caller).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rc {

struct BinaryCacheKey {
    unsigned long long high = 0;
    unsigned long long low = 0;

    static BinaryCacheKey of(const std::string& expanded_source, const std::string& options,
                             const std::string& device_name, const std::string& driver_version);
    std::string hex() const;
};

enum class CacheLookup { kHit, kMiss, kCorrupt };

class BinaryCache {
   public:
    // An empty directory disables the cache.
    explicit BinaryCache(std::filesystem::path directory);

    bool enabled() const { return !directory_.empty(); }
    const std::filesystem::path& directory() const { return directory_; }
    std::filesystem::path entry_path(const BinaryCacheKey& key) const;

    // The binary stored under `key`; kCorrupt (and no binary) when the entry exists but is
    // truncated or fails its key or checksum test.
    CacheLookup load(const BinaryCacheKey& key, std::vector<unsigned char>& binary) const;

    // The same for an entry's bytes: the fuzz target's entry.
    static CacheLookup parse_entry(const std::string& bytes, const BinaryCacheKey& key,
                                   std::vector<unsigned char>& binary);

    // Stores the binary (atomically). Failures to write are reported as warnings only: the
    // cache is an optimisation.
    void store(const BinaryCacheKey& key, const std::vector<unsigned char>& binary) const;

    // $RADCACHE_CACHE_DIR, else $XDG_CACHE_HOME/radcache, else ~/.cache/radcache.
    static std::filesystem::path default_directory();

   private:
    std::filesystem::path directory_;
};

}  // namespace rc
