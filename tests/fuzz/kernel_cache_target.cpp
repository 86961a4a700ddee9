// Fuzz target: a kernel binary-cache entry. The key it must match is the one its header names,
// and for inputs whose ninth byte is even the checksum field is made to match its payload, so
// that both the refusals and the accepted entries are reached.
#include <OpenImageIO/hash.h>

#include <cstring>

#include "device/binary_cache.h"
#include "fuzz_targets.h"

namespace rc::fuzz {

int kernel_cache(const uint8_t* data, size_t size) {
    std::string bytes(reinterpret_cast<const char*>(data), size);
    // The header (binary_cache.cpp): magic[8], key high, key low, size, checksum (uint64 each).
    constexpr size_t kHeader = 40;
    BinaryCacheKey key;
    if (bytes.size() >= kHeader) {
        std::memcpy(&key.high, bytes.data() + 8, sizeof key.high);
        std::memcpy(&key.low, bytes.data() + 16, sizeof key.low);
        if ((static_cast<unsigned char>(bytes[8]) & 1u) == 0) {
            const uint64_t sum =
                OIIO::farmhash::Fingerprint64(bytes.data() + kHeader, bytes.size() - kHeader);
            std::memcpy(bytes.data() + 32, &sum, sizeof sum);
        }
    }
    std::vector<unsigned char> binary;
    const CacheLookup lookup = BinaryCache::parse_entry(bytes, key, binary);
    if (lookup == CacheLookup::kHit && binary.size() + kHeader != bytes.size()) {
        __builtin_trap();  // an accepted entry must be exactly its header and payload
    }
    return 0;
}

}  // namespace rc::fuzz
