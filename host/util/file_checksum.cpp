#include "util/file_checksum.h"

#include <OpenImageIO/hash.h>

#include <cstdint>
#include <cstring>

namespace rc {

void append_checksum(std::string& bytes) {
    const uint64_t sum = OIIO::farmhash::Fingerprint64(bytes.data(), bytes.size());
    bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
}

bool has_valid_checksum(const std::string& bytes) {
    uint64_t stored;
    if (bytes.size() < sizeof stored) {
        return false;
    }
    const size_t covered = bytes.size() - sizeof stored;
    std::memcpy(&stored, bytes.data() + covered, sizeof stored);
    return OIIO::farmhash::Fingerprint64(bytes.data(), covered) == stored;
}

}  // namespace rc
