#include "device/binary_cache.h"

#include <OpenImageIO/hash.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "util/error.h"
#include "util/file_io.h"
#include "util/log.h"

namespace rc {
namespace {

constexpr char kMagic[8] = {'R', 'C', 'K', 'B', 'I', 'N', '0', '1'};
// The largest entry read (a program binary is some megabytes).
constexpr uint64_t kMaxEntryBytes = uint64_t{1} << 30;

struct EntryHeader {
    char magic[8];
    unsigned long long key_high;
    unsigned long long key_low;
    unsigned long long size;
    unsigned long long checksum;
};

unsigned long long checksum_of(const unsigned char* bytes, size_t size) {
    return OIIO::farmhash::Fingerprint64(reinterpret_cast<const char*>(bytes), size);
}

}  // namespace

BinaryCacheKey BinaryCacheKey::of(const std::string& expanded_source, const std::string& options,
                                  const std::string& device_name,
                                  const std::string& driver_version) {
    std::string material;
    material.reserve(expanded_source.size() + 256);
    material += "radcache-binary-cache-1\n";
    for (const std::string* part : {&options, &device_name, &driver_version, &expanded_source}) {
        material += std::to_string(part->size()) + ":" + *part + "\n";
    }
    const OIIO::farmhash::uint128_t hash =
        OIIO::farmhash::Fingerprint128(material.data(), material.size());
    return {OIIO::farmhash::Uint128High64(hash), OIIO::farmhash::Uint128Low64(hash)};
}

std::string BinaryCacheKey::hex() const {
    char text[33];
    std::snprintf(text, sizeof text, "%016llx%016llx", high, low);
    return text;
}

BinaryCache::BinaryCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

std::filesystem::path BinaryCache::default_directory() {
    if (const char* dir = std::getenv("RADCACHE_CACHE_DIR"); dir != nullptr && *dir != '\0') {
        return dir;
    }
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
        return std::filesystem::path(xdg) / "radcache";
    }
    if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
        return std::filesystem::path(home) / ".cache" / "radcache";
    }
    return {};
}

std::filesystem::path BinaryCache::entry_path(const BinaryCacheKey& key) const {
    return directory_ / (key.hex() + ".clbin");
}

CacheLookup BinaryCache::load(const BinaryCacheKey& key, std::vector<unsigned char>& binary) const {
    binary.clear();
    if (!enabled()) {
        return CacheLookup::kMiss;
    }
    const std::filesystem::path path = entry_path(key);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        return CacheLookup::kMiss;
    }
    std::string bytes;
    try {
        bytes = read_file(path, kMaxEntryBytes, "kernel cache entry");
    } catch (const Error&) {
        return CacheLookup::kCorrupt;
    }
    return parse_entry(bytes, key, binary);
}

CacheLookup BinaryCache::parse_entry(const std::string& bytes, const BinaryCacheKey& key,
                                     std::vector<unsigned char>& binary) {
    binary.clear();
    EntryHeader header;
    if (bytes.size() < sizeof header) {
        return CacheLookup::kCorrupt;
    }
    std::memcpy(&header, bytes.data(), sizeof header);
    const size_t payload = bytes.size() - sizeof header;
    if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 || header.key_high != key.high ||
        header.key_low != key.low || header.size != payload || payload == 0) {
        return CacheLookup::kCorrupt;
    }
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + sizeof header;
    if (checksum_of(data, payload) != header.checksum) {
        return CacheLookup::kCorrupt;
    }
    binary.assign(data, data + payload);
    return CacheLookup::kHit;
}

void BinaryCache::store(const BinaryCacheKey& key, const std::vector<unsigned char>& binary) const {
    if (!enabled() || binary.empty()) {
        return;
    }
    EntryHeader header;
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.key_high = key.high;
    header.key_low = key.low;
    header.size = binary.size();
    header.checksum = checksum_of(binary.data(), binary.size());
    std::string bytes(sizeof header + binary.size(), '\0');
    std::memcpy(bytes.data(), &header, sizeof header);
    std::memcpy(bytes.data() + sizeof header, binary.data(), binary.size());
    try {
        std::error_code error;
        std::filesystem::create_directories(directory_, error);
        if (error) {
            throw Error(directory_.string() + ": " + error.message());
        }
        write_file_atomically(entry_path(key), bytes, WriteTiming::kNow);
    } catch (const Error& failure) {
        log_warning(std::string("kernel binary cache not written: ") + failure.what());
    }
}

}  // namespace rc
